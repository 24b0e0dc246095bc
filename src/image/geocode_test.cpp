#include "ris/image/geocode.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_simulation.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

RadarParams test_radar() {
  toml::table doc = toml::parse(R"(name = "t"
mode = "slar"
frequency = "9.4 GHz"
polarisation = "HH"
pulse_width = "0.1 us"
near_range = "12000 m"
far_range = "20000 m"
azimuth_beamwidth = "0.05 deg"
[track]
altitude = "6000 m"
heading = "0 deg"
near_edge_distance = "12000 m"
)");
  return radar_from_toml(doc, "radar.toml");
}

TEST(Geocode, BrightPatchOnAFlatSceneLandsOnItsOwnCells) {
  // 20 m cells; a 20 x 20 cell patch of the brightest category on a dark plain.
  Scene s = Scene::flat(150, 200, 20.0, 50.0f, 0);
  const int r0 = 60, r1 = 80, c0 = 90, c1 = 110;
  for (int r = r0; r < r1; ++r)
    for (int c = c0; c < c1; ++c) s.category[s.index(r, c)] = 5;
  const RadarParams radar = test_radar();
  const SlarSimulation sim = simulate_slar(s, radar, test::CosineSigma0Source());
  const std::vector<float> map =
      geocode_slant_image(s, sim.track, sim.image, sim.image.mean_power_w);

  // Bright cells (above the geometric mean of patch and plain levels): their
  // bounding box is the patch's, to within one cell (pixel edges do not fall
  // on cell edges), and their centroid is the patch's within half a cell.
  double patch_mean = 0, plain_mean = 0;
  int n_patch = 0, n_plain = 0;
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const float v = map[s.index(r, c)];
      if (std::isnan(v)) continue;
      const bool in = r >= r0 + 2 && r < r1 - 2 && c >= c0 + 2 && c < c1 - 2;
      const bool out = r < r0 - 2 || r >= r1 + 2 || c < c0 - 2 || c >= c1 + 2;
      if (in) patch_mean += v, ++n_patch;
      if (out) plain_mean += v, ++n_plain;
    }
  ASSERT_GT(n_patch, 0);
  ASSERT_GT(n_plain, 0);
  patch_mean /= n_patch;
  plain_mean /= n_plain;
  // gamma 0.30 against 0.05: six times brighter.
  EXPECT_NEAR(patch_mean / plain_mean, 6.0, 0.6);
  const double threshold = std::sqrt(patch_mean * plain_mean);
  int rmin = s.rows, rmax = -1, cmin = s.cols, cmax = -1;
  double rc = 0, cc = 0;
  int n = 0;
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const float v = map[s.index(r, c)];
      if (!(v > threshold)) continue;
      rmin = std::min(rmin, r), rmax = std::max(rmax, r);
      cmin = std::min(cmin, c), cmax = std::max(cmax, c);
      rc += r, cc += c, ++n;
    }
  EXPECT_NEAR(rmin, r0, 1);
  EXPECT_NEAR(rmax, r1 - 1, 1);
  EXPECT_NEAR(cmin, c0, 1);
  EXPECT_NEAR(cmax, c1 - 1, 1);
  EXPECT_NEAR(rc / n, 0.5 * (r0 + r1 - 1), 0.5);
  EXPECT_NEAR(cc / n, 0.5 * (c0 + c1 - 1), 0.5);
}

TEST(Geocode, CellsOutsideTheImageOrWithoutDataAreNaN) {
  Scene s = Scene::flat(40, 60, 20.0, 0.0f, 1);
  s.valid[s.index(10, 10)] = 0;
  const SlarSimulation sim = simulate_slar(s, test_radar(), test::CosineSigma0Source());
  std::vector<float> ones(sim.image.mean_power_w.size(), 1.0f);
  const std::vector<float> map = geocode_slant_image(s, sim.track, sim.image, ones);
  EXPECT_TRUE(std::isnan(map[s.index(10, 10)]));
  EXPECT_EQ(map[s.index(20, 30)], 1.0f);
  // A track far away sees nothing of the scene: all NaN.
  Track away = sim.track;
  away.start_x_m += 1e6;
  const std::vector<float> none = geocode_slant_image(s, away, sim.image, ones);
  for (float v : none) EXPECT_TRUE(std::isnan(v));
}

}  // namespace
}  // namespace ris
