#include "ris/scene/fractal_noise.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <vector>

#include "ris/util/error.h"

namespace ris {
namespace {

FractalParams params(double hurst) {
  FractalParams p;
  p.rows = 300;
  p.cols = 260;
  p.cell_m = 10.0;
  p.relief_m = 500.0;
  p.base_m = 100.0;
  p.hurst = hurst;
  p.seed = 9;
  return p;
}

Scene make(const FractalParams& p, int block) {
  const FractalNoise gen(p);
  Scene s = Scene::flat(p.rows, p.cols, p.cell_m, 0.0f, 0);
  for (int r0 = 0; r0 < p.rows; r0 += block) {
    const int n = std::min(block, p.rows - r0);
    gen.rows(r0, n, s.elevation_m.data() + s.index(r0, 0), s.category.data() + s.index(r0, 0));
  }
  return s;
}

// Any block of rows, on any thread count, is the same field.
TEST(FractalNoise, BlocksAndThreadsGiveTheSameField) {
  const FractalParams p = params(0.8);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const Scene a = make(p, 300);
  omp_set_num_threads(2);
  const Scene b = make(p, 7);
  omp_set_num_threads(saved);
  EXPECT_EQ(a.elevation_m, b.elevation_m);
}

// Heights span [base, base + relief] and the roughness follows H: the
// variogram exponent estimated between 8 and 32 cells is near H (value noise
// is an approximate fBm: within 0.15).
TEST(FractalNoise, SpansTheReliefWithTheRoughnessOfH) {
  for (double h : {0.4, 0.8}) {
    const Scene s = make(params(h), 64);
    const auto [lo, hi] = std::minmax_element(s.elevation_m.begin(), s.elevation_m.end());
    EXPECT_GE(*lo, 100.0f);
    EXPECT_LE(*hi, 600.0f);
    EXPECT_GT(*hi - *lo, 0.95f * 500.0f);
    EXPECT_NEAR(estimate_hurst(s, 8, 32), h, 0.15) << "H = " << h;
  }
}

TEST(FractalNoise, PatchesAreThoseOfSpectralSynthesis) {
  FractalParams p = params(0.8);
  p.patch_categories = {3, 5, 7};
  p.patch_size_m = 400.0;
  const Scene noise = make(p, 50);
  const Scene spectral = fractal_terrain(p);
  EXPECT_EQ(noise.category, spectral.category);
  p.hurst = 1.5;
  EXPECT_THROW(FractalNoise{p}, InputError);
}

}  // namespace
}  // namespace ris
