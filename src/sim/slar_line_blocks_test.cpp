#include "ris/sim/slar_line_blocks.h"
#include "build_paths.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "ris/perf/bench_setup.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

using test::same_bytes;

Scene test_scene() {
  return test::rugged_test_scene();
}

void expect_same(const SlarSimulation& ref, const SlarSimulation& fused, const std::string& what) {
  EXPECT_TRUE(ref.geometry.flags.size() > 0) << what;
  EXPECT_TRUE(fused.geometry.flags.empty()) << what << ": fused keeps no per-sample arrays";
  EXPECT_TRUE(same_bytes(ref.image.mean_power_w, fused.image.mean_power_w)) << what;
  EXPECT_TRUE(same_bytes(ref.image.area_m2, fused.image.area_m2)) << what;
  EXPECT_TRUE(same_bytes(ref.image.mask, fused.image.mask)) << what;
  EXPECT_TRUE(same_bytes(ref.image.mapped_count, fused.image.mapped_count)) << what;
  EXPECT_TRUE(same_bytes(ref.image.visible_count, fused.image.visible_count)) << what;
  EXPECT_EQ(ref.image.samples_in_swath, fused.image.samples_in_swath) << what;
  EXPECT_TRUE(same_bytes(ref.scene_maps.mask, fused.scene_maps.mask)) << what;
  EXPECT_TRUE(same_bytes(ref.scene_maps.local_incidence_deg, fused.scene_maps.local_incidence_deg))
      << what;
  EXPECT_EQ(ref.geometry.nodata_samples, fused.geometry.nodata_samples) << what;
  EXPECT_EQ(ref.geometry.shadow_samples, fused.geometry.shadow_samples) << what;
  EXPECT_EQ(ref.geometry.back_facing_samples, fused.geometry.back_facing_samples) << what;
  EXPECT_EQ(ref.geometry.layover_samples, fused.geometry.layover_samples) << what;
  EXPECT_EQ(ref.geometry.nodata_cells, fused.geometry.nodata_cells) << what;
  EXPECT_GT(fused.geometry.shadow_samples, 0) << what << ": the test scene casts shadow";
}

// Runs the stage path (keep_geometry) and the fused path for each heading,
// both look sides and 1 and 2 threads, and expects the same bytes; the
// heading `pattern_heading_deg` also gets a Gaussian elevation pattern.
void expect_fused_equals_stages(const std::vector<double>& headings_deg, double pattern_heading_deg,
                                bool sar = false) {
  const Scene s = test_scene();
  const test::CosineSigma0Source src({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  const RadarParams base =
      load_radar(std::string(ris::test::data_dir()) + "/radars/seed-fig4-5.toml");
  const int saved = omp_get_max_threads();
  for (double heading_deg : headings_deg) {
    for (LookSide side : {LookSide::right, LookSide::left}) {
      for (int threads : {1, 2}) {
        RadarParams r = bench_radar(base, s, deg_to_rad(heading_deg));
        r.track.look_side = side;
        r.track.altitude_m = 600.0;  // steep enough for shadow over 30 m of relief
        r.track.near_edge_ground_m = 1500.0;
        r = bench_radar(r, s, deg_to_rad(heading_deg));
        if (heading_deg == pattern_heading_deg) {
          r.elevation_pattern.kind = ElevationPattern::Kind::gaussian;
          r.elevation_pattern.beamwidth_rad = deg_to_rad(30.0);
          r.elevation_pattern.boresight_rad = deg_to_rad(65.0);
        }
        if (sar) {  // incoherent SAR: range and azimuth windows, noise
          r.mode = RadarMode::sar;
          r.sar.range_resolution_m = 2.5 * r.range_bin_m;
          r.sar.azimuth_resolution_m = 14.0;
          r.sar.range_looks = 1;
          r.sar.azimuth_looks = 2;
          r.sar.nesz = 1e-3;
        }
        omp_set_num_threads(threads);
        SlarOptions keep;
        keep.keep_geometry = true;
        const SlarSimulation ref = simulate_slar(s, r, src, keep);
        const SlarSimulation fused = simulate_slar(s, r, src);
        const std::string what = fmt::format("heading {} side {} threads {}", heading_deg,
                                             side == LookSide::right ? "right" : "left", threads);
        expect_same(ref, fused, what);
        EXPECT_GT(std::count(fused.scene_maps.mask.begin(), fused.scene_maps.mask.end(), 0), 100)
            << what << ": cells imaged";
      }
    }
  }
  omp_set_num_threads(saved);
}

// The fused per-line path gives the same bytes as geometry + image formation
// + scene maps run one after another, for every axis-aligned heading and both
// look sides, with no-data cells, an elevation pattern and 1 or 2 threads.
TEST(SlarLineBlocks, FusedEqualsReferenceStagesByteForByte) {
  expect_fused_equals_stages({0.0, 90.0, 180.0, 270.0}, 90.0);
}

// Oblique tracks (bilinear sampling at half a cell): the fused path, line by
// line with the scene maps scattered per line, gives the same bytes as the
// stages, for headings in every quadrant.
TEST(SlarLineBlocks, FusedObliqueEqualsReferenceStagesByteForByte) {
  expect_fused_equals_stages({30.0, 100.0, 225.0, 318.0}, 100.0);
}

// The incoherent SAR (constant azimuth window, range window wider than the
// bins, NESZ noise) takes the fused path too, with the same bytes.
TEST(SlarLineBlocks, FusedSarEqualsReferenceStagesByteForByte) {
  expect_fused_equals_stages({0.0, 30.0, 270.0}, -1.0, true);
}

TEST(SlarLineBlocks, AppliesOnlyToOneLinePerCellAlongAnAxis) {
  const Scene s = test_scene();
  const RadarParams base =
      load_radar(std::string(ris::test::data_dir()) + "/radars/seed-fig4-5.toml");
  const RadarParams along = bench_radar(base, s, 0.0);
  const Track t0 = resolve_track(along.track, s, "r");
  EXPECT_TRUE(fused_slar_applies(s, slar_geometry_layout(s, t0, 0.0)));
  EXPECT_FALSE(fused_slar_applies(s, slar_geometry_layout(s, t0, 7.0)));  // other spacing
  const RadarParams oblique = bench_radar(base, s, deg_to_rad(30.0));
  const Track t30 = resolve_track(oblique.track, s, "r");
  EXPECT_FALSE(fused_slar_applies(s, slar_geometry_layout(s, t30, 0.0)));
  // form_slar_image_fused runs oblique tracks too, not other spacings along an axis.
  EXPECT_TRUE(fused_slar_image_applies(s, slar_geometry_layout(s, t30, 0.0)));
  EXPECT_FALSE(fused_slar_image_applies(s, slar_geometry_layout(s, t0, 7.0)));
}

}  // namespace
}  // namespace ris
