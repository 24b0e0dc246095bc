// End-to-end: `ris greytone` on a small mean-power raster.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"
#include "ris/scene/scene_io.h"
#include "test_inputs.h"
#include "test_util.h"

namespace ris {
namespace {

constexpr int kLines = 40, kBins = 241;  // the seed figure-4-5 radar's bins

std::filesystem::path write_power(const test::TempDir& dir) {
  std::vector<float> p(static_cast<size_t>(kLines) * kBins, 2e-12f);
  for (int k = 0; k < kBins; ++k) p[static_cast<size_t>(k)] = std::nanf("");  // no data line 0
  const auto path = dir / "power.tif";
  write_geotiff<float>(path, p.data(), kBins, kLines, nullptr, std::nan(""));
  return path;
}

TEST(GreytoneCli, SpeckledUniformAreaCentresOnTheAutoGreytone) {
  test::TempDir dir;
  const auto power = write_power(dir);
  const auto png = dir / "g.png";
  const test::RunResult run =
      test::run_ris("greytone " + power.string() + " --out " + png.string() + " --speckled " +
                    (dir / "s.tif").string() + " --seed 5");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const RasterF64 g = read_raster_f64(png);
  ASSERT_EQ(g.cols, kBins);
  ASSERT_EQ(g.rows, kLines);
  for (int k = 0; k < kBins; ++k) EXPECT_EQ(g.data[static_cast<size_t>(k)], 0.0);  // no data
  // N from 1 to 1.10 across the swath (equation 16): single-look speckle.
  // E[log10 Y] = (psi(N) - ln N) / ln 10 for Y ~ Gamma(N, 1/N): -0.2507
  // decades at N = 1, -0.2254 at N = 1.10; with 76.5 greytones per decade
  // (the film of seed-fig4-5.toml) the mean greytone lies between
  // 128 - 19.2 = 108.8 and 128 - 17.2 = 110.8 (clamping at 0 adds < 0.1).
  double sum = 0;
  for (size_t i = kBins; i < g.data.size(); ++i) sum += g.data[i];
  const double mean = sum / static_cast<double>(g.data.size() - kBins);
  // 1.3: 3 standard errors (sd of log10 Y at N = 1 is pi / (sqrt 6 ln 10) = 0.557
  // decades = 42.6 greytones, over 9400 pixels).
  EXPECT_GT(mean, 108.8 - 1.3);
  EXPECT_LT(mean, 110.8 + 1.3);
  const RasterF64 s = read_raster_f64(dir / "s.tif");
  EXPECT_TRUE(std::isnan(s.data[0]));
  // The same seed gives the same bytes; another seed does not.
  const auto png2 = dir / "g2.png";
  ASSERT_EQ(test::run_ris("greytone " + power.string() + " --out " + png2.string() + " --seed 5")
                .exit_code,
            0);
  EXPECT_EQ(test::read_file(png), test::read_file(png2));
  ASSERT_EQ(test::run_ris("greytone " + power.string() + " --out " + png2.string() + " --seed 6")
                .exit_code,
            0);
  EXPECT_NE(test::read_file(png), test::read_file(png2));
}

// Re-running the greytone stage on a simulation's saved mean power, with the
// same radar and seed, reproduces the simulation's slant-range image; another
// film changes it without a new simulation.
TEST(GreytoneCli, ReproducesTheSimulationsSlantRangeImage) {
  test::TempDir dir;
  Scene scene = Scene::flat(40, 120, 10.0, 0.0f, 1);
  for (int r = 10; r < 25; ++r) {
    for (int c = 50; c < 70; ++c) scene.elevation_m[scene.index(r, c)] = 100.0f;
  }
  write_scene_geotiff(scene, dir / "scene.tif");
  // Few independent samples, so the fading (and the seed) shows.
  const std::string radar_text = "independent_samples = 3\n" + test::kSmallSlarRadar;
  test::write_file(dir / "radar.toml", radar_text);
  test::write_file(dir / "library.toml", test::constant_gamma_library({{1, "grass", -12.0, ""}}));
  const auto out = dir / "out";
  const test::RunResult sim =
      test::run_ris("simulate --scene " + (dir / "scene.tif").string() + " --radar " +
                    (dir / "radar.toml").string() + " --backscatter " +
                    (dir / "library.toml").string() + " --out " + out.string() + " --seed 11");
  ASSERT_EQ(sim.exit_code, 0) << sim.output;
  const auto again = dir / "again.png";
  const std::string greytone = "greytone " + (out / "mean_power_slant.tif").string() + " --radar " +
                               (dir / "radar.toml").string() + " --out ";
  ASSERT_EQ(test::run_ris(greytone + again.string() + " --seed 11").exit_code, 0);
  const RasterF64 a = read_raster_f64(out / "slant_range.png");
  const RasterF64 b = read_raster_f64(again);
  ASSERT_EQ(a.cols, b.cols);
  ASSERT_EQ(a.rows, b.rows);
  EXPECT_EQ(a.data, b.data);
  // Another film (gamma 2 instead of 1): a new image from the same mean power.
  test::write_file(dir / "film.toml", radar_text + "[film]\ngamma = 2.0\n");
  const auto film = dir / "film.png";
  ASSERT_EQ(test::run_ris("greytone " + (out / "mean_power_slant.tif").string() + " --radar " +
                          (dir / "film.toml").string() + " --out " + film.string() + " --seed 11")
                .exit_code,
            0);
  EXPECT_NE(read_raster_f64(film).data, a.data);
}

TEST(GreytoneCli, RasterThatDoesNotMatchTheRadarFails) {
  test::TempDir dir;
  std::vector<float> p(100, 1.0f);
  write_geotiff<float>(dir / "p.tif", p.data(), 10, 10, nullptr);
  const test::RunResult r =
      test::run_ris("greytone " + (dir / "p.tif").string() + " --out " + (dir / "g.png").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("241"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "g.png"));
}

}  // namespace
}  // namespace ris
