#include "ris/sensor/track_view.h"

#include <fmt/format.h>

#include <algorithm>
#include <limits>

#include "ris/util/error.h"

namespace ris {

TrackSceneExtent track_scene_extent(const Track& track, const Scene& grid) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  TrackSceneExtent e{kInf, -kInf, kInf, -kInf};
  for (int r : {0, grid.rows}) {
    for (int c : {0, grid.cols}) {
      const auto [x, y] = grid.world_from_grid(c, r);
      const auto [s, u] = track.along_cross(x, y);
      e.s_min_m = std::min(e.s_min_m, s);
      e.s_max_m = std::max(e.s_max_m, s);
      e.u_min_m = std::min(e.u_min_m, u);
      e.u_max_m = std::max(e.u_max_m, u);
    }
  }
  return e;
}

namespace {

const char* side_name(LookSide side) {
  return side == LookSide::right ? "right" : "left";
}

}  // namespace

void check_scene_in_view(const TrackSpec& spec, const Track& track, const Scene& grid,
                         const std::string& file) {
  const TrackSceneExtent e = track_scene_extent(track, grid);
  // The track's end points as the file names them (scene metres or
  // latitude/longitude); a heading track is laid out to see the scene.
  const bool geo = spec.geo.has_value();
  const char* start_key = geo ? "track.start_latlon" : "track.start";
  const char* end_key = geo ? "track.end_latlon" : "track.end";
  const char* looks = side_name(track.look_side);
  const char* other =
      side_name(track.look_side == LookSide::right ? LookSide::left : LookSide::right);
  if (!(e.u_max_m > 0.0)) {
    throw InputError(
        file, "track.look_side",
        fmt::format("the radar looks {} of its track, but the whole scene lies on the track's "
                    "{} ({:.0f} to {:.0f} m from it), so no cell is seen; expected look_side = "
                    "\"{}\", or {} and {} swapped so that the scene lies on the track's {}",
                    looks, other, -e.u_max_m, -e.u_min_m, other, start_key, end_key, looks));
  }
  if (e.s_max_m < 0.0 || e.s_min_m > track.length_m) {
    const bool behind = e.s_max_m < 0.0;
    throw InputError(
        file, behind ? start_key : end_key,
        fmt::format("the whole scene lies {} the track ({:.0f} to {:.0f} m along it, the "
                    "track {:.0f} m long), so no line passes it; expected {} and {} that run "
                    "past the scene (or heading and near_edge_distance, which lay the track "
                    "along the whole scene)",
                    behind ? "behind the start of" : "past the end of", e.s_min_m, e.s_max_m,
                    track.length_m, start_key, end_key));
  }
}

}  // namespace ris
