#include "ris/sim/slar_simulation.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <filesystem>

#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_products.h"
#include "slar_fixtures.h"
#include "test_inputs.h"
#include "test_util.h"

namespace ris {
namespace {

constexpr double kCell = 10.0;

RadarParams small_radar() {
  return radar_from_toml(toml::parse(test::kSmallSlarRadar), "r.toml");
}

Scene small_scene() {
  Scene s = Scene::flat(40, 200, kCell, 0.0f, 1);
  for (int r = 10; r < 30; ++r)
    for (int c = 80; c < 100; ++c) s.elevation_m[s.index(r, c)] = 120.0f;
  return s;
}

TEST(SlarSimulation, SameSeedSameBytesForOneAndTwoThreads) {
  const Scene s = small_scene();
  const test::CosineSigma0Source src;
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const SlarSimulation a = simulate_slar(s, small_radar(), src);
  const SlarPictures pa = render_slar(a, 5);
  omp_set_num_threads(2);
  const SlarSimulation b = simulate_slar(s, small_radar(), src);
  const SlarPictures pb = render_slar(b, 5);
  const SlarPictures pc = render_slar(b, 6);
  omp_set_num_threads(saved);
  ASSERT_EQ(pa.speckled_power_w.size(), pb.speckled_power_w.size());
  EXPECT_EQ(std::memcmp(pa.speckled_power_w.data(), pb.speckled_power_w.data(),
                        pa.speckled_power_w.size() * sizeof(float)),
            0);
  EXPECT_EQ(pa.slant_grey, pb.slant_grey);
  EXPECT_EQ(pa.ground_grey, pb.ground_grey);
  EXPECT_NE(pb.slant_grey, pc.slant_grey);  // the seed matters
  // Re-rendering does not touch the geometry or the mean power.
  EXPECT_EQ(a.image.mean_power_w, b.image.mean_power_w);
}

TEST(SlarSimulation, RangeSwitchOffGivesEveryPixelTheReferenceRange) {
  const Scene s = small_scene();
  const test::CosineSigma0Source src;
  RadarParams radar = small_radar();
  const SlarSimulation on = simulate_slar(s, radar, src);
  radar.switches.range = false;
  const SlarSimulation off = simulate_slar(s, radar, src);
  EXPECT_TRUE(off.range_corrected);
  const double r1 = radar.reference.range_m;
  ASSERT_GT(r1, 0.0);
  for (int line : {5, 20}) {
    for (int b = 0; b < on.image.bins; b += 7) {
      const std::size_t i = on.image.index(line, b);
      const double q = on.image.range.centre_m(b) / r1;
      EXPECT_NEAR(off.image.mean_power_w[i], on.image.mean_power_w[i] * q * q * q * q,
                  1e-5 * on.image.mean_power_w[i] * q * q * q * q + 1e-30);
    }
  }
}

TEST(SlarSimulation, AreaSwitchOffGivesEveryPixelTheReferenceArea) {
  const Scene s = small_scene();
  const test::CosineSigma0Source src;
  RadarParams radar = small_radar();
  const SlarSimulation on = simulate_slar(s, radar, src);
  radar.switches.area = false;
  const SlarSimulation off = simulate_slar(s, radar, src);
  const double a1 = radar.reference.area_m2;
  ASSERT_GT(a1, 0.0);
  const std::size_t i = on.image.index(3, 40);
  ASSERT_GT(on.image.area_m2[i], 0.0f);
  EXPECT_NEAR(off.image.mean_power_w[i] / on.image.mean_power_w[i], a1 / on.image.area_m2[i],
              1e-5 * a1 / on.image.area_m2[i]);
}

TEST(SlarSimulation, GroundRangeReferenceIsTheMedianElevation) {
  Scene s = Scene::flat(20, 200, kCell, 25.0f, 1);
  for (int c = 0; c < 50; ++c) s.elevation_m[s.index(3, c)] = 80.0f;
  const SlarSimulation sim = simulate_slar(s, small_radar(), test::CosineSigma0Source());
  EXPECT_DOUBLE_EQ(sim.ground_grid.reference_height_m, 25.0);
  SlarOptions o;
  o.reference_height_m = 10.0;
  EXPECT_DOUBLE_EQ(
      simulate_slar(s, small_radar(), test::CosineSigma0Source(), o).ground_grid.reference_height_m,
      10.0);
}

TEST(SlarProducts, WritesEveryProductIntoTheFolder) {
  const Scene s = small_scene();
  const SlarSimulation sim = simulate_slar(s, small_radar(), test::CosineSigma0Source());
  const SlarPictures pic = render_slar(sim, 1);
  test::TempDir dir;
  write_slar_products(dir / "out", s, sim, pic, SlarRunInfo{"s.tif", "r.toml", "b.toml", 1, 2});
  for (const char* name : {"slant_range.png", "ground_range.png", "mean_power_slant.tif",
                           "speckled_power_slant.tif", "mask_slant.tif", "scene_mask.tif",
                           "local_incidence_deg.tif", "shadowmap.txt", "metadata.json"}) {
    EXPECT_TRUE(std::filesystem::exists(dir / "out" / name)) << name;
  }
  const nlohmann::json meta = slar_metadata(s, sim, pic, SlarRunInfo{"s.tif", "r.toml", "b", 1, 2});
  EXPECT_EQ(meta["software"]["version"], RIS_VERSION);
  EXPECT_EQ(meta["derived"]["radar"]["range_bins"], sim.image.bins);
  EXPECT_EQ(meta["inputs"]["radar"]["track"]["altitude_m"], 3000.0);
  EXPECT_GT(meta["derived"]["geometry"]["shadow_samples"].get<int>(), 0);
}

}  // namespace
}  // namespace ris
