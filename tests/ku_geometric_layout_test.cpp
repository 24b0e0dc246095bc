// The standard scene's layout under the seed's two SLARs: every solid casts a
// shadow, and no shadow or layover zone of one solid reaches another solid
// (data/scenes/ku-geometric.toml promises both; docs/scene-format.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>

#include "build_paths.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/scene/scene_builder.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/track.h"

namespace ris {
namespace {

struct LayoutCheck {
  int lines_with_solids = 0;
  int lines_with_solids_but_no_shadow = 0;
  int zones_touching = 0;         // pairs of neighbouring solids whose zones meet
  int min_gap_samples = 1 << 30;  // clearest sample count between two zones
  std::int64_t shadow_samples = 0;
  std::int64_t layover_samples = 0;
};

// Along each zero-Doppler line, a solid is a maximal run of raised samples.
// Its zone is the run, extended towards near range over the contiguous
// layover samples in front of it and towards far range over the contiguous
// shadowed or back-facing samples behind it. The zones of neighbouring solids
// must leave at least one clear sample between them: then no shadow reaches
// another solid or its layover, and no layover zones merge.
LayoutCheck check_layout(const std::string& radar_file) {
  const RadarParams radar = load_radar(radar_file);
  const Scene scene =
      build_scene_file(std::string(ris::test::data_dir()) + "/scenes/ku-geometric.toml");
  const Track track = resolve_track(radar.track, scene, radar.source_file);
  const SlarGeometry g = compute_slar_geometry(scene, track, 0.0, radar.source_file);
  LayoutCheck out;
  out.shadow_samples = g.shadow_samples;
  out.layover_samples = g.layover_samples;
  constexpr float kRaised_m = 0.01f;
  const auto dark = sample_flag::kShadow | sample_flag::kBackFacing;
  for (int line = 0; line < g.lines; ++line) {
    auto flags = [&](int j) { return g.flags[g.index(line, j)]; };
    auto seen = [&](int j) {
      return (flags(j) & (sample_flag::kUnseen | sample_flag::kNoData)) == 0;
    };
    auto raised = [&](int j) { return seen(j) && g.height_m[g.index(line, j)] > kRaised_m; };
    bool has_solid = false, has_shadow = false;
    int previous_zone_end = -1;
    for (int j = 0; j < g.samples; ++j) {
      if (seen(j) && (flags(j) & sample_flag::kShadow)) has_shadow = true;
      if (!raised(j) || (j > 0 && raised(j - 1))) continue;
      // A solid starts at j: find its run [j, end] and its zone [west, east].
      has_solid = true;
      int end = j;
      while (end + 1 < g.samples && raised(end + 1)) ++end;
      int west = j;
      while (west - 1 >= 0 && seen(west - 1) && (flags(west - 1) & sample_flag::kLayover)) --west;
      int east = end;
      while (east + 1 < g.samples && seen(east + 1) && !raised(east + 1) &&
             (flags(east + 1) & dark)) {
        ++east;
      }
      if (previous_zone_end >= 0) {
        if (west <= previous_zone_end + 1) ++out.zones_touching;
        out.min_gap_samples = std::min(out.min_gap_samples, west - previous_zone_end - 1);
      }
      previous_zone_end = east;
      j = end;
    }
    if (has_solid) {
      ++out.lines_with_solids;
      if (!has_shadow) ++out.lines_with_solids_but_no_shadow;
    }
  }
  return out;
}

void expect_clean_layout(const std::string& radar_name) {
  const LayoutCheck c = check_layout(std::string(ris::test::data_dir()) + "/radars/" + radar_name);
  // Every one of the 700 lines but the 80-row checkerboard band and the
  // gaps between lanes crosses a solid; at least the four lanes' worth.
  EXPECT_GT(c.lines_with_solids, 400) << radar_name;
  EXPECT_EQ(c.lines_with_solids_but_no_shadow, 0) << radar_name;
  EXPECT_EQ(c.zones_touching, 0) << radar_name;
  // The layout leaves room: the closest zones are still 20+ cells apart.
  EXPECT_GE(c.min_gap_samples, 20) << radar_name;
  std::printf(
      "%s: %d lines cross solids; closest zones %d samples apart; %lld shadow, "
      "%lld layover samples\n",
      radar_name.c_str(), c.lines_with_solids, c.min_gap_samples,
      static_cast<long long>(c.shadow_samples), static_cast<long long>(c.layover_samples));
  EXPECT_GT(c.shadow_samples, 10000) << radar_name;
  EXPECT_GT(c.layover_samples, 1000) << radar_name;
}

TEST(KuGeometricLayout, ShadowsAndLayoverStayClearUnderTheSeedRadars) {
  expect_clean_layout("seed-fig4-5.toml");  // 20 deg near-range depression
  expect_clean_layout("seed-fig4-6.toml");  // 24 deg
}

}  // namespace
}  // namespace ris
