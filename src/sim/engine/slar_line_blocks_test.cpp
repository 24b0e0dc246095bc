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
#include "ris/sim/sar_coherent.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"
#include "slar_stage_reference.h"

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

// The kept-geometry sink's per-sample geometry is the stage path's, byte for
// byte (NaN where unseen or no data included), with the same counts.
void expect_same_geometry(const SlarGeometry& ref, const SlarGeometry& kept,
                          const std::string& what) {
  EXPECT_EQ(ref.lines, kept.lines) << what;
  EXPECT_EQ(ref.samples, kept.samples) << what;
  EXPECT_TRUE(same_bytes(ref.height_m, kept.height_m)) << what << ": height";
  EXPECT_TRUE(same_bytes(ref.slant_range_m, kept.slant_range_m)) << what << ": range";
  EXPECT_TRUE(same_bytes(ref.incidence_rad, kept.incidence_rad)) << what << ": incidence";
  EXPECT_TRUE(same_bytes(ref.local_incidence_rad, kept.local_incidence_rad))
      << what << ": local incidence";
  EXPECT_TRUE(same_bytes(ref.area_m2, kept.area_m2)) << what << ": area";
  EXPECT_TRUE(same_bytes(ref.range_near_end_m, kept.range_near_end_m)) << what << ": near end";
  EXPECT_TRUE(same_bytes(ref.range_far_end_m, kept.range_far_end_m)) << what << ": far end";
  EXPECT_TRUE(same_bytes(ref.category, kept.category)) << what << ": category";
  EXPECT_TRUE(same_bytes(ref.flags, kept.flags)) << what << ": flags";
  EXPECT_EQ(ref.nodata_samples, kept.nodata_samples) << what;
  EXPECT_EQ(ref.shadow_samples, kept.shadow_samples) << what;
  EXPECT_EQ(ref.back_facing_samples, kept.back_facing_samples) << what;
  EXPECT_EQ(ref.layover_samples, kept.layover_samples) << what;
  EXPECT_EQ(ref.nodata_cells, kept.nodata_cells) << what;
}

// Runs the stage path (the reference, tests/slar_stage_reference.h), the
// engine keeping the per-sample geometry and the engine without it for each
// heading,
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
        const SlarSimulation ref = test::simulate_slar_by_stages(s, r, src);
        const SlarSimulation kept = simulate_slar(s, r, src, keep);
        const SlarSimulation fused = simulate_slar(s, r, src);
        const std::string what = fmt::format("heading {} side {} threads {}", heading_deg,
                                             side == LookSide::right ? "right" : "left", threads);
        expect_same(ref, fused, what);
        expect_same_geometry(ref.geometry, kept.geometry, what + ", kept");
        EXPECT_TRUE(same_bytes(ref.image.mean_power_w, kept.image.mean_power_w)) << what;
        EXPECT_TRUE(same_bytes(ref.scene_maps.mask, kept.scene_maps.mask)) << what;
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

// Point targets on cells of the rugged scene: open ground, beside and behind
// the tower (hidden from some look directions), near the no-data hole.
std::vector<PointTarget> rugged_scene_targets(const Scene& s) {
  std::vector<PointTarget> out;
  int index = 0;
  for (const auto& [r, c] : {std::pair{10, 20}, std::pair{30, 55}, std::pair{30, 75},
                             std::pair{45, 50}, std::pair{19, 43}, std::pair{55, 85}}) {
    PointTarget t;
    t.name = fmt::format("t{}", index);
    const auto [x, y] = s.world_from_grid(c + 0.5, r + 0.5);
    t.x_m = x;
    t.y_m = y;
    t.height_m = 2.0;
    t.rcs_m2 = 500.0;
    t.source_file = "targets.toml";
    t.index = index++;
    out.push_back(t);
  }
  return out;
}

// The engine run with point targets (and the coherent SAR's element power)
// against the stage path: the same image, point returns, hidden targets,
// per-sample geometry and scene maps, and the same coherent intensity.
// Returns the number of targets hidden.
std::size_t expect_engine_equals_stages_with_targets(const RadarParams& r,
                                                     const std::string& what) {
  const Scene s = test_scene();
  const test::CosineSigma0Source src({1, 2, 3, 4, 5, 6, 7, 8, 9, 10});
  SlarOptions o;
  o.targets = rugged_scene_targets(s);
  const SlarSimulation ref = test::simulate_slar_by_stages(s, r, src, o);
  const SlarSimulation eng = simulate_slar(s, r, src, o);
  EXPECT_TRUE(same_bytes(ref.image.mean_power_w, eng.image.mean_power_w)) << what;
  EXPECT_TRUE(same_bytes(ref.image.area_m2, eng.image.area_m2)) << what;
  EXPECT_TRUE(same_bytes(ref.image.mask, eng.image.mask)) << what;
  EXPECT_TRUE(same_bytes(ref.image.mapped_count, eng.image.mapped_count)) << what;
  EXPECT_TRUE(same_bytes(ref.image.visible_count, eng.image.visible_count)) << what;
  EXPECT_TRUE(same_bytes(ref.image.element_power_w, eng.image.element_power_w)) << what;
  EXPECT_TRUE(same_bytes(ref.image.point_power_w, eng.image.point_power_w)) << what;
  EXPECT_EQ(ref.image.samples_in_swath, eng.image.samples_in_swath) << what;
  EXPECT_TRUE(same_bytes(ref.scene_maps.mask, eng.scene_maps.mask)) << what;
  EXPECT_TRUE(same_bytes(ref.scene_maps.local_incidence_deg, eng.scene_maps.local_incidence_deg))
      << what;
  EXPECT_EQ(ref.hidden_targets, eng.hidden_targets) << what;
  EXPECT_EQ(ref.point_returns.size(), eng.point_returns.size()) << what;
  if (ref.point_returns.size() != eng.point_returns.size()) return 0;
  for (std::size_t k = 0; k < ref.point_returns.size(); ++k) {
    const PointReturn &a = ref.point_returns[k], &b = eng.point_returns[k];
    EXPECT_EQ(a.line, b.line) << what << " target " << k;
    EXPECT_EQ(a.along_m, b.along_m) << what << " target " << k;
    EXPECT_EQ(a.slant_range_m, b.slant_range_m) << what << " target " << k;
    EXPECT_EQ(a.look_rad, b.look_rad) << what << " target " << k;
    EXPECT_EQ(a.rcs_m2, b.rcs_m2) << what << " target " << k;
  }
  // The targets are not all hidden, nor all seen (the tower hides some for
  // some look directions; the scene's corners fall outside some swaths).
  EXPECT_GT(eng.point_returns.size(), 0u) << what;
  const bool coherent = r.mode == RadarMode::sar && r.sar.coherent;
  if (coherent || !fused_slar_image_applies(s, eng.geometry)) {
    expect_same_geometry(ref.geometry, eng.geometry, what);
  } else {
    EXPECT_TRUE(eng.geometry.flags.empty()) << what << ": targets need no kept geometry";
  }
  if (coherent) {
    EXPECT_FALSE(eng.image.element_power_w.empty()) << what;
    EXPECT_TRUE(same_bytes(coherent_sar_intensity(ref, 7), coherent_sar_intensity(eng, 7))) << what;
  }
  return eng.hidden_targets.size();
}

RadarParams rugged_radar(double heading_deg, LookSide side) {
  const Scene s = test_scene();
  const RadarParams base =
      load_radar(std::string(ris::test::data_dir()) + "/radars/seed-fig4-5.toml");
  RadarParams r = bench_radar(base, s, deg_to_rad(heading_deg));
  r.track.look_side = side;
  r.track.altitude_m = 600.0;
  r.track.near_edge_ground_m = 1500.0;
  return bench_radar(r, s, deg_to_rad(heading_deg));
}

void make_sar(RadarParams& r, bool coherent) {
  r.mode = RadarMode::sar;
  r.sar.range_resolution_m = 2.5 * r.range_bin_m;
  r.sar.azimuth_resolution_m = 14.0;
  r.sar.range_looks = 1;
  r.sar.azimuth_looks = 2;
  r.sar.nesz = 1e-3;
  r.sar.coherent = coherent;
}

// Point targets and the coherent SAR go through the engine (the kept-geometry
// sink, the targets placed per line) with the stage path's bytes, along the
// axes and off them, on 1 and 2 threads.
TEST(SlarLineBlocks, TargetsAndCoherentSarEqualStagesByteForByte) {
  const int saved = omp_get_max_threads();
  std::size_t hidden = 0;
  for (double heading_deg : {0.0, 90.0, 30.0, 225.0}) {
    for (LookSide side : {LookSide::right, LookSide::left}) {
      for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        const std::string what = fmt::format("heading {} side {} threads {}", heading_deg,
                                             side == LookSide::right ? "right" : "left", threads);
        RadarParams slar = rugged_radar(heading_deg, side);
        hidden += expect_engine_equals_stages_with_targets(slar, what + ", SLAR");
        RadarParams sar = slar;
        make_sar(sar, false);
        hidden += expect_engine_equals_stages_with_targets(sar, what + ", SAR");
        make_sar(sar, true);
        hidden += expect_engine_equals_stages_with_targets(sar, what + ", coherent SAR");
      }
    }
  }
  omp_set_num_threads(saved);
  // Some targets are hidden (shadow, off the lines), so both outcomes are
  // compared.
  EXPECT_GT(hidden, 0u);
}

// Lines along an axis that are not one per cell row or column (a line
// spacing other than the cell's) go through the engine too, cell by cell,
// with the scene maps made from the kept geometry: the stage path's bytes.
TEST(SlarLineBlocks, LinesNotOnePerCellEqualStagesByteForByte) {
  const int saved = omp_get_max_threads();
  for (double heading_deg : {0.0, 90.0, 180.0}) {
    for (double spacing_m : {4.0, 23.0}) {
      for (int threads : {1, 2}) {
        omp_set_num_threads(threads);
        RadarParams r = rugged_radar(heading_deg, LookSide::right);
        r.azimuth_line_spacing_m = spacing_m;
        const std::string what =
            fmt::format("heading {} spacing {} threads {}", heading_deg, spacing_m, threads);
        expect_engine_equals_stages_with_targets(r, what);
        make_sar(r, true);
        expect_engine_equals_stages_with_targets(r, what + ", coherent SAR");
      }
    }
  }
  omp_set_num_threads(saved);
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
