#include "ris/geometry/swath_coverage.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "ris/sensor/track_view.h"

namespace ris {

namespace {

// Ground distance of slant range r from a track dh above the ground
// (0 inside the nadir circle: no ground that near).
double ground_of_slant(double r_m, double dh_m) {
  return r_m > dh_m ? std::sqrt(r_m * r_m - dh_m * dh_m) : 0.0;
}

}  // namespace

SwathCoverage swath_coverage(const Track& track, const Scene& grid, const SlantRangeBins& swath,
                             double reference_height_m) {
  SwathCoverage c;
  c.reference_height_m = reference_height_m;
  const double dh = track.altitude_m - reference_height_m;
  const double u_near = ground_of_slant(swath.near_m, dh);
  const double u_far = ground_of_slant(swath.far_m(), dh);
  const TrackSceneExtent e = track_scene_extent(track, grid);
  c.across_scene_m = e.u_max_m - e.u_min_m;
  c.across_imaged_m = std::max(0.0, std::min(e.u_max_m, u_far) - std::max(e.u_min_m, u_near));
  c.along_scene_m = e.s_max_m - e.s_min_m;
  c.along_imaged_m = std::max(0.0, std::min(e.s_max_m, track.length_m) - std::max(e.s_min_m, 0.0));
  // A gap of up to 2 % of the scene's width at an edge is no missed side
  // (the near edge is rarely exactly at the swath's).
  const double slack_m = 0.02 * c.across_scene_m;
  c.misses_near = u_near > e.u_min_m + slack_m && u_near < e.u_max_m;
  c.misses_far = u_far < e.u_max_m - slack_m && u_far > e.u_min_m;
  // The cells' centres, every step-th row and column (a track off the grid
  // axes crosses them obliquely: the fraction is not the product of the two
  // extents' fractions).
  const int row_step = std::max(1, grid.rows / 512), col_step = std::max(1, grid.cols / 512);
  std::int64_t in = 0, all = 0;
  for (int r = 0; r < grid.rows; r += row_step) {
    for (int col = 0; col < grid.cols; col += col_step) {
      const auto [x, y] = grid.world_from_grid(col + 0.5, r + 0.5);
      const auto [s, u] = track.along_cross(x, y);
      in += (s >= 0.0 && s <= track.length_m && u >= u_near && u <= u_far) ? 1 : 0;
      ++all;
    }
  }
  c.cell_fraction = all > 0 ? double(in) / double(all) : 1.0;
  return c;
}

std::optional<std::string> swath_coverage_warning(const SwathCoverage& c) {
  if (!(c.cell_fraction < 0.5)) return std::nullopt;
  // 1 % of the scene's extent short counts as covering it (cell centres).
  const bool across_short = c.across_imaged_m < 0.99 * c.across_scene_m;
  const bool along_short = c.along_imaged_m < 0.99 * c.along_scene_m;
  std::string part;
  if (c.across_imaged_m <= 0.0) {
    part = "none of it";
  } else if (c.misses_near && c.misses_far) {
    part = "a strip in the middle";
  } else if (c.misses_far) {
    part = "near side";
  } else if (c.misses_near) {
    part = "far side";
  }
  std::string what = fmt::format("the swath images {:.1f} km of the scene's {:.1f} km across track",
                                 c.across_imaged_m / 1000.0, c.across_scene_m / 1000.0);
  if (!part.empty()) what += " (" + part + ")";
  if (along_short) {
    what += fmt::format(" and {:.1f} km of its {:.1f} km along track", c.along_imaged_m / 1000.0,
                        c.along_scene_m / 1000.0);
  }
  std::string fix;
  if (across_short || !along_short)
    fix = "widen sweep_length or move the track (near_edge_distance, sweep_delay)";
  if (along_short) {
    fix += std::string(fix.empty() ? "" : "; ") + "lengthen the track (track.start, track.end)";
  }
  return fmt::format(
      "{}: {:.0f} % of its cells, on flat ground at the reference height {:.0f} m; {}", what,
      100.0 * c.cell_fraction, c.reference_height_m, fix);
}

}  // namespace ris
