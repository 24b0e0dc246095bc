// The fused oblique run (slar_oblique_lines.cpp) against the stage path for a
// track that crosses the scene: cells behind the track (u <= 0) and beyond
// its ends take no line or sample, so the per-row runs of the scene-map
// scatter are cut at both ends by the exact check, not by the scene's edge.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <string>

#include "build_paths.h"
#include "ris/geometry/scene_geometry_maps.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_simulation.h"
#include "slar_fixtures.h"
#include "slar_stage_reference.h"

namespace ris {
namespace {

using test::same_bytes;

// The 900 m x 600 m rugged test scene (x in [0, 900], y in [0, 600]) under a
// 600 m-high track from (x0, y0) to (x1, y1), a swath from 400 to 900 m of
// slant range.
RadarParams crossing_radar(double x0, double y0, double x1, double y1, LookSide side) {
  RadarParams r = load_radar(std::string(ris::test::data_dir()) + "/radars/seed-fig4-5.toml");
  r.track.kind = TrackSpec::Kind::endpoints;
  r.track.start_x_m = x0;
  r.track.start_y_m = y0;
  r.track.end_x_m = x1;
  r.track.end_y_m = y1;
  r.track.altitude_m = 600.0;
  r.track.look_side = side;
  r.near_slant_range_m = 400.0;
  r.range_bins = static_cast<int>(std::floor(500.0 / r.range_bin_m));
  r.far_slant_range_m = r.near_slant_range_m + r.range_bins * r.range_bin_m;
  return r;
}

TEST(SlarObliqueLines, TrackAcrossTheSceneFusedEqualsStagesByteForByte) {
  const Scene s = test::rugged_test_scene();
  const test::CosineSigma0Source src({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const int saved = omp_get_max_threads();
  struct Case {
    double x0, y0, x1, y1;
    LookSide side;
  };
  // Headings ~49 deg and ~229 deg (the same line reversed), a steep one,
  // and two a fraction of a degree off the grid axes (rows of the scene-map
  // scatter nearly a whole line long; each row's cells outside the swath
  // found exactly).
  for (const Case& k : {Case{200.0, 100.0, 600.0, 450.0, LookSide::right},
                        Case{600.0, 450.0, 200.0, 100.0, LookSide::left},
                        Case{420.0, 50.0, 520.0, 560.0, LookSide::right},
                        Case{420.0, 50.0, 421.0, 560.0, LookSide::right},
                        Case{100.0, 300.0, 800.0, 298.5, LookSide::right}}) {
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const RadarParams r = crossing_radar(k.x0, k.y0, k.x1, k.y1, k.side);
      const SlarSimulation ref = test::simulate_slar_by_stages(s, r, src);
      const SlarSimulation fused = simulate_slar(s, r, src);
      const std::string what = "track from (" + std::to_string(k.x0) + ", " + std::to_string(k.y0) +
                               "), threads " + std::to_string(threads);
      ASSERT_FALSE(ref.geometry.direct_sampling) << what;
      EXPECT_TRUE(same_bytes(ref.image.mean_power_w, fused.image.mean_power_w)) << what;
      EXPECT_TRUE(same_bytes(ref.image.mask, fused.image.mask)) << what;
      EXPECT_EQ(ref.image.samples_in_swath, fused.image.samples_in_swath) << what;
      EXPECT_TRUE(same_bytes(ref.scene_maps.mask, fused.scene_maps.mask)) << what;
      EXPECT_TRUE(
          same_bytes(ref.scene_maps.local_incidence_deg, fused.scene_maps.local_incidence_deg))
          << what;
      // Cells behind the track and beyond its ends are outside the swath,
      // cells in front are imaged.
      const CellSampleFrame f = cell_sample_frame(s, ref.geometry);
      int behind_or_beyond = 0, imaged = 0;
      for (int row = 0; row < s.rows; ++row) {
        for (int col = 0; col < s.cols; ++col) {
          const std::uint8_t m = fused.scene_maps.mask[s.index(row, col)];
          int line = 0, j = 0;
          if (!cell_sample(f, row, col, line, j)) {
            EXPECT_TRUE(m & scene_flag::kOutsideSwath) << what << " cell " << row << ", " << col;
            ++behind_or_beyond;
          } else if (m == 0) {
            ++imaged;
          }
        }
      }
      EXPECT_GT(behind_or_beyond, 500) << what;
      EXPECT_GT(imaged, 500) << what;
    }
  }
  omp_set_num_threads(saved);
}

}  // namespace
}  // namespace ris
