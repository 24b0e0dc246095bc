#include "ris/sim/slar_simulation.h"
#include "build_paths.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include "ris/image/greytone.h"
#include "ris/image/greytone_image.h"
#include "ris/image/ground_range.h"
#include "ris/perf/bench_setup.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_products.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
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

// render_slar runs per line in one pass; its bytes are those of the
// whole-image steps it stands for (make_greytone_image: NaN for no data,
// fading, greytones; to_ground_range, to_ground_range_nearest and greytones
// of the ground-range power), for both fading laws, fading off, a coherent
// intensity, 1 and 2 threads, with no-data pixels.
// The image, scene maps and pictures are not zero-filled before they are
// written (ris/util/default_init_allocator.h: UninitVector), so every byte
// must be written by the run: a run on a heap full of freed garbage gives the
// same bytes as the first run, along an axis and oblique, 1 and 2 threads.
TEST(SlarSimulation, OutputsDoNotDependOnWhatTheHeapHeld) {
  const Scene s = test::rugged_test_scene();
  const test::CosineSigma0Source src({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const RadarParams base =
      load_radar(std::string(ris::test::data_dir()) + "/radars/seed-fig4-5.toml");
  const auto bytes_of = [](const auto& v) {
    const auto* p = reinterpret_cast<const unsigned char*>(v.data());
    return std::vector<unsigned char>(p, p + v.size() * sizeof(v[0]));
  };
  const auto all_bytes = [&](const SlarSimulation& sim, const SlarPictures& pic) {
    return std::vector<std::vector<unsigned char>>{bytes_of(sim.image.mean_power_w),
                                                   bytes_of(sim.image.area_m2),
                                                   bytes_of(sim.image.mask),
                                                   bytes_of(sim.image.mapped_count),
                                                   bytes_of(sim.image.visible_count),
                                                   bytes_of(sim.scene_maps.mask),
                                                   bytes_of(sim.scene_maps.local_incidence_deg),
                                                   bytes_of(pic.speckled_power_w),
                                                   bytes_of(pic.slant_grey),
                                                   bytes_of(pic.ground_power_w),
                                                   bytes_of(pic.ground_mask),
                                                   bytes_of(pic.ground_grey)};
  };
  const int saved = omp_get_max_threads();
  for (const double heading_deg : {0.0, 90.0, 30.0}) {
    RadarParams r = bench_radar(base, s, deg_to_rad(heading_deg));
    r.track.altitude_m = 600.0;  // shadow over the scene's relief
    r.track.near_edge_ground_m = 1500.0;
    r = bench_radar(r, s, deg_to_rad(heading_deg));
    for (const int threads : {1, 2}) {
      omp_set_num_threads(threads);
      std::vector<std::vector<unsigned char>> first;
      std::size_t largest = 0;
      {
        const SlarSimulation sim = simulate_slar(s, r, src);
        const SlarPictures pic = render_slar(sim, 3);
        first = all_bytes(sim, pic);
        for (const auto& b : first) largest = std::max(largest, b.size());
      }
      // Garbage in freed blocks of every size up to the largest output,
      // which the next run's allocations reuse.
      {
        std::vector<std::vector<unsigned char>> junk;
        for (std::size_t n = 64; n <= 2 * largest; n += n / 4 + 64) junk.emplace_back(n, 0xA5);
        for (std::size_t n = 64; n <= 2 * largest; n += n / 4 + 64) junk.emplace_back(n, 0xFF);
      }
      const SlarSimulation sim = simulate_slar(s, r, src);
      const SlarPictures pic = render_slar(sim, 3);
      const auto again = all_bytes(sim, pic);
      ASSERT_EQ(again.size(), first.size());
      for (std::size_t k = 0; k < first.size(); ++k)
        EXPECT_TRUE(again[k] == first[k])
            << "output " << k << " heading " << heading_deg << " threads " << threads;
    }
  }
  omp_set_num_threads(saved);
}

TEST(SlarSimulation, RenderEqualsTheWholeImageSteps) {
  Scene s = small_scene();
  for (int r = 0; r < 40; ++r) {
    for (int c = 150; c < 165; ++c) {
      s.valid[s.index(r, c)] = 0;
      s.category[s.index(r, c)] = kNoDataCategory;
    }
  }
  const test::CosineSigma0Source src;
  const int saved = omp_get_max_threads();
  for (const char* extra : {"", "[film]\nfading = \"seed\"\n", "[film.terms]\nfading = false\n"}) {
    const RadarParams radar = radar_from_toml(toml::parse(test::kSmallSlarRadar + extra), "r.toml");
    const SlarSimulation sim = simulate_slar(s, radar, src);
    const SlarImage& img = sim.image;
    std::vector<float> intensity(img.mean_power_w.size());
    for (std::size_t i = 0; i < intensity.size(); ++i)
      intensity[i] = 0.5f * img.mean_power_w[i] * float(1 + i % 3);
    for (const bool coherent : {false, true}) {
      // The whole-image steps.
      std::vector<std::uint8_t> no_data(img.mask.size());
      for (std::size_t i = 0; i < no_data.size(); ++i)
        no_data[i] = (img.mask[i] & pixel_flag::kNoData) ? 1 : 0;
      RadarParams r = sim.radar;
      if (coherent) r.switches.fading = false;
      GreytoneImage g = make_greytone_image(r, img.mean_power_w, img.lines, img.bins,
                                            img.range.near_m, img.range.bin_m, 9, no_data);
      if (coherent) {
        g.speckled_power_w = intensity;
        greytones(g.speckled_power_w, g.greytone, g.map, no_data);
      }
      const std::vector<float> ground =
          to_ground_range(g.speckled_power_w, img.lines, img.range, sim.ground_grid);
      const std::vector<std::uint8_t> ground_mask = to_ground_range_nearest(
          img.mask, img.lines, img.range, sim.ground_grid, pixel_flag::kNoData);
      std::vector<std::uint8_t> ground_no_data(ground_mask.size()), ground_grey(ground.size());
      for (std::size_t i = 0; i < ground_mask.size(); ++i)
        ground_no_data[i] = (ground_mask[i] & pixel_flag::kNoData) ? 1 : 0;
      greytones(ground, ground_grey, g.map, ground_no_data);
      ASSERT_GT(std::count(no_data.begin(), no_data.end(), 1), 0);
      ASSERT_GT(std::count_if(ground.begin(), ground.end(), [](float v) { return std::isnan(v); }),
                0);
      for (const int threads : {1, 2}) {
        omp_set_num_threads(threads);
        const SlarPictures pic = coherent ? render_slar(sim, 9, intensity) : render_slar(sim, 9);
        ASSERT_EQ(pic.speckled_power_w.size(), g.speckled_power_w.size());
        EXPECT_EQ(std::memcmp(pic.speckled_power_w.data(), g.speckled_power_w.data(),
                              g.speckled_power_w.size() * sizeof(float)),
                  0)
            << extra << coherent << threads;
        EXPECT_TRUE(std::ranges::equal(pic.slant_grey, g.greytone));
        ASSERT_EQ(pic.ground_power_w.size(), ground.size());
        EXPECT_EQ(
            std::memcmp(pic.ground_power_w.data(), ground.data(), ground.size() * sizeof(float)),
            0);
        EXPECT_TRUE(std::ranges::equal(pic.ground_mask, ground_mask));
        EXPECT_TRUE(std::ranges::equal(pic.ground_grey, ground_grey));
        EXPECT_EQ(pic.looks, g.looks_per_bin);
        EXPECT_EQ(pic.reference_power_w, g.map.reference_power_w());
      }
    }
  }
  omp_set_num_threads(saved);
}

// Terrain at or above the sensor is an InputError naming the highest cell with
// data (a higher cell without data does not count), on both paths.
TEST(SlarSimulation, TerrainAboveTheSensorNamesTheHighestCell) {
  for (const bool keep_geometry : {false, true}) {
    Scene s = small_scene();
    s.elevation_m[s.index(5, 7)] = 3100.0f;  // the radar flies at 3000 m
    s.elevation_m[s.index(6, 7)] = 3000.0f;
    s.elevation_m[s.index(20, 30)] = 9000.0f;
    s.valid[s.index(20, 30)] = 0;
    SlarOptions o;
    o.keep_geometry = keep_geometry;
    try {
      simulate_slar(s, small_radar(), test::CosineSigma0Source(), o);
      ADD_FAILURE() << "expected an InputError";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("3100.0 m (scene row 5, column 7)"), std::string::npos)
          << e.what();
    }
    s.elevation_m[s.index(5, 7)] = 2999.0f;
    s.elevation_m[s.index(6, 7)] = 2999.9f;
    EXPECT_NO_THROW(simulate_slar(s, small_radar(), test::CosineSigma0Source(), o));
  }
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
