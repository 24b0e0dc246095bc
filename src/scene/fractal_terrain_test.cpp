#include "ris/scene/fractal_terrain.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "ris/util/error.h"

namespace ris {
namespace {

FractalParams params(double hurst, std::uint64_t seed) {
  FractalParams p;
  p.rows = 257;
  p.cols = 385;
  p.cell_m = 20.0;
  p.relief_m = 1200.0;
  p.base_m = 300.0;
  p.hurst = hurst;
  p.seed = seed;
  return p;
}

TEST(FractalTerrain, SameSeedSameBytesOnAnyThreadCount) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  Scene one = fractal_terrain(params(0.7, 42));
  omp_set_num_threads(std::max(2, threads));
  Scene many = fractal_terrain(params(0.7, 42));
  omp_set_num_threads(threads);
  EXPECT_EQ(one.elevation_m, many.elevation_m);
  Scene other = fractal_terrain(params(0.7, 43));
  EXPECT_NE(one.elevation_m, other.elevation_m);
}

TEST(FractalTerrain, ReliefSpansExactlyBaseToBasePlusRelief) {
  Scene s = fractal_terrain(params(0.8, 5));
  ASSERT_EQ(s.rows, 257);
  ASSERT_EQ(s.cols, 385);
  const auto [lo, hi] = std::minmax_element(s.elevation_m.begin(), s.elevation_m.end());
  EXPECT_NEAR(*lo, 300.0, 1e-3);
  EXPECT_NEAR(*hi, 1500.0, 1e-3);
  EXPECT_DOUBLE_EQ(s.dx_m, 20.0);
  EXPECT_EQ(std::count(s.valid.begin(), s.valid.end(), 1), static_cast<long>(s.size()));
}

TEST(FractalTerrain, VariogramExponentFollowsTheHurstExponent) {
  // fBm has var(z(x+h) - z(x)) ~ h^(2H). On the synthesised field the
  // variogram slope between 8 and 64 cells, averaged over two seeds, is
  // within 0.06 of H for 0.3 <= H <= 0.8 (the spread between seeds is about
  // 0.03; below 0.3 the grid cut-off biases it up, above 0.8 down).
  for (double hurst : {0.3, 0.5, 0.8}) {
    double mean = 0.0;
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      FractalParams p = params(hurst, seed);
      p.rows = p.cols = 512;
      mean += estimate_hurst(fractal_terrain(p), 8, 64) / 2.0;
    }
    EXPECT_NEAR(mean, hurst, 0.06) << "H = " << hurst;
  }
  // Rougher terrain has more cell-to-cell variation at the same relief.
  Scene rough = fractal_terrain(params(0.3, 9));
  Scene smooth = fractal_terrain(params(0.9, 9));
  auto step_rms = [](const Scene& s) {
    double sum = 0;
    for (int r = 0; r < s.rows; ++r)
      for (int c = 0; c + 1 < s.cols; ++c) {
        const double d = s.elevation_m[s.index(r, c + 1)] - s.elevation_m[s.index(r, c)];
        sum += d * d;
      }
    return std::sqrt(sum / double(s.rows * (s.cols - 1)));
  };
  EXPECT_GT(step_rms(rough), 3.0 * step_rms(smooth));
}

TEST(FractalTerrain, PatchesUseTheGivenCategoriesAtAboutTheGivenSize) {
  FractalParams p = params(0.8, 11);
  p.patch_categories = {2, 5, 9};
  p.patch_size_m = 500.0;
  Scene s = fractal_terrain(p);
  std::set<std::uint16_t> seen(s.category.begin(), s.category.end());
  EXPECT_EQ(seen, (std::set<std::uint16_t>{2, 5, 9}));
  // Category changes along rows: a patch spans ~ patch_size / cell = 25 cells,
  // so boundaries are crossed every ~25 cells (between 10 and 60).
  std::size_t changes = 0;
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c + 1 < s.cols; ++c)
      changes += s.category[s.index(r, c)] != s.category[s.index(r, c + 1)];
  const double run = double(s.rows * (s.cols - 1)) / double(std::max<std::size_t>(changes, 1));
  EXPECT_GT(run, 10.0);
  EXPECT_LT(run, 60.0);
  Scene again = fractal_terrain(p);
  EXPECT_EQ(s.category, again.category);
}

TEST(FractalTerrain, BadParametersNameTheOption) {
  auto expect = [](FractalParams p, const std::string& key) {
    try {
      fractal_terrain(p);
      FAIL() << key;
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
    }
  };
  FractalParams p = params(0.5, 1);
  p.hurst = 1.0;
  expect(p, "--hurst");
  p = params(0.5, 1);
  p.relief_m = -1.0;
  expect(p, "--relief");
  p = params(0.5, 1);
  p.cell_m = 0.0;
  expect(p, "--cell-size");
  p = params(0.5, 1);
  p.patch_categories = {1};
  expect(p, "--patch-size");
  p = params(0.5, 1);
  p.rows = 1;
  expect(p, "--size");
  p = params(0.5, 1);
  p.rows = p.cols = 2000000;
  expect(p, "--size");
}

}  // namespace
}  // namespace ris
