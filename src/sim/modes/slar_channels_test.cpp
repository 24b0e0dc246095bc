// The channel axis (ris/sim/slar_channels.h): every channel of a
// multi-channel run is the simulation its channel alone gives, byte for byte
// (images, counts, scene maps, ground grid), along a grid axis and off it,
// SLAR and incoherent SAR, on 1 and 2 threads; channels with another
// geometry, the coherent SAR and point targets are refused naming the key.
#include "ris/sim/slar_channels.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <string>
#include <vector>

#include "build_paths.h"
#include "ris/perf/bench_setup.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"
#include "stream_fixtures.h"

namespace ris {
namespace {

template <class V>
bool same_bytes(const V& a, const V& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(a[0])) == 0);
}

void expect_same_simulation(const SlarSimulation& alone, const SlarSimulation& in_run,
                            const std::string& what) {
  const SlarImage& a = alone.image;
  const SlarImage& b = in_run.image;
  EXPECT_EQ(a.lines, b.lines) << what;
  EXPECT_EQ(a.bins, b.bins) << what;
  EXPECT_TRUE(same_bytes(a.mean_power_w, b.mean_power_w)) << what << ": mean power";
  EXPECT_TRUE(same_bytes(a.area_m2, b.area_m2)) << what << ": area";
  EXPECT_TRUE(same_bytes(a.mask, b.mask)) << what << ": mask";
  EXPECT_TRUE(same_bytes(a.mapped_count, b.mapped_count)) << what << ": mapped count";
  EXPECT_TRUE(same_bytes(a.visible_count, b.visible_count)) << what << ": visible count";
  EXPECT_EQ(a.samples_in_swath, b.samples_in_swath) << what;
  EXPECT_TRUE(same_bytes(alone.noise_power_w, in_run.noise_power_w)) << what << ": noise";
  EXPECT_EQ(alone.geometry.shadow_samples, in_run.geometry.shadow_samples) << what;
  EXPECT_EQ(alone.geometry.layover_samples, in_run.geometry.layover_samples) << what;
  EXPECT_EQ(alone.geometry.nodata_samples, in_run.geometry.nodata_samples) << what;
  EXPECT_EQ(alone.geometry.nodata_cells, in_run.geometry.nodata_cells) << what;
  EXPECT_TRUE(same_bytes(alone.scene_maps.mask, in_run.scene_maps.mask)) << what;
  EXPECT_TRUE(
      same_bytes(alone.scene_maps.local_incidence_deg, in_run.scene_maps.local_incidence_deg))
      << what;
  EXPECT_EQ(alone.ground_grid.count, in_run.ground_grid.count) << what;
  EXPECT_EQ(alone.ground_grid.spacing_m, in_run.ground_grid.spacing_m) << what;
  EXPECT_EQ(alone.categories, in_run.categories) << what;
  EXPECT_EQ(alone.warnings, in_run.warnings) << what;
}

// Two other backscatter laws than the cosine one (a channel's source).
class FlatSigma0Source : public test::CosineSigma0Source {
 public:
  using CosineSigma0Source::CosineSigma0Source;
  double sigma0(std::uint16_t c, double, const RadarBand& b) const override {
    return 0.01 * (c + 1) * b.frequency_hz / 1e9;
  }
};

TEST(SlarChannels, EachChannelIsItsOwnRunByteForByte) {
  const Scene scene = test::rugged_test_scene();
  const test::CosineSigma0Source cosine({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const FlatSigma0Source flat({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const int saved = omp_get_max_threads();
  for (const bool sar : {false, true}) {
    for (const double heading : {0.0, 90.0, 30.0}) {
      RadarParams base = test::stream_test_radar(scene, heading);
      if (sar) {
        // The shipped stripmap SAR, incoherent, its swath over this scene.
        RadarParams s =
            load_radar(std::string(test::data_dir()) + "/radars/sar-x-band-stripmap.toml");
        s.sar.coherent = false;
        base = bench_radar(s, scene, deg_to_rad(heading));
      }
      const RadarParams c_vv = radar_at_band(base, 5.3e9, Polarisation::VV);
      RadarParams l_hh = radar_at_band(base, 1.25e9, Polarisation::HH);
      l_hh.transmit_power_w *= 2.0;
      const std::vector<SlarChannel> channels{
          {base, &cosine, ""}, {c_vv, &cosine, ""}, {l_hh, &flat, ""}, {base, &flat, ""}};
      for (const int threads : {1, 2}) {
        omp_set_num_threads(threads);
        const std::string tag = std::string(sar ? "SAR" : "SLAR") + " heading " +
                                std::to_string(int(heading)) + ", " + std::to_string(threads) +
                                " threads";
        SlarOptions o;
        o.keep_geometry = heading == 30.0;  // the first channel keeps it (the study's case)
        const std::vector<SlarSimulation> run = simulate_slar_channels(scene, channels, o);
        ASSERT_EQ(run.size(), channels.size());
        for (std::size_t c = 0; c < channels.size(); ++c) {
          SlarOptions alone;
          alone.keep_geometry = c == 0 && o.keep_geometry;
          const SlarSimulation one =
              simulate_slar(scene, channels[c].radar, *channels[c].sigma0, alone);
          expect_same_simulation(one, run[c], tag + ", channel " + std::to_string(c));
        }
        // The channels differ (a channel is not the first one's copy).
        EXPECT_FALSE(same_bytes(run[0].image.mean_power_w, run[1].image.mean_power_w)) << tag;
        EXPECT_FALSE(same_bytes(run[0].image.mean_power_w, run[3].image.mean_power_w)) << tag;
      }
    }
  }
  omp_set_num_threads(saved);
}

TEST(SlarChannels, AChannelWithAnotherGeometryIsRefusedNamingTheKey) {
  const Scene scene = test::rugged_test_scene();
  const test::CosineSigma0Source cosine({0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const RadarParams base = test::stream_test_radar(scene, 0.0);
  const auto refused_key = [&](const RadarParams& other, const SlarOptions& o = {}) {
    const std::vector<SlarChannel> channels{{base, &cosine, ""}, {other, &cosine, ""}};
    try {
      (void)simulate_slar_channels(scene, channels, o);
    } catch (const InputError& e) {
      return e.key();
    }
    return std::string("(accepted)");
  };
  RadarParams higher = base;
  higher.track.altitude_m += 100.0;
  EXPECT_EQ(refused_key(higher), "track");
  RadarParams later = base;
  later.near_slant_range_m += 50.0;
  later.far_slant_range_m += 50.0;
  EXPECT_EQ(refused_key(later), "sweep_delay");
  RadarParams coherent =
      load_radar(std::string(test::data_dir()) + "/radars/sar-x-band-stripmap.toml");
  coherent.track = base.track;
  coherent.near_slant_range_m = base.near_slant_range_m;
  coherent.far_slant_range_m = base.far_slant_range_m;
  EXPECT_NE(refused_key(coherent), "(accepted)");
  SlarOptions with_targets;
  PointTarget t;
  t.name = "t";
  const auto [x, y] = scene.world_from_grid(0.5 * scene.cols, 0.5 * scene.rows);
  t.x_m = x;
  t.y_m = y;
  t.rcs_m2 = 100.0;
  with_targets.targets.push_back(t);
  EXPECT_EQ(refused_key(radar_at_band(base, 5.3e9, Polarisation::HH), with_targets), "targets");
  EXPECT_EQ(refused_key(radar_at_band(base, 5.3e9, Polarisation::VV)), "(accepted)");
}

}  // namespace
}  // namespace ris
