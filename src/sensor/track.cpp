#include "ris/sensor/track.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "ris/sensor/geo_track.h"
#include "ris/util/error.h"

namespace ris {

namespace {
// g = a x z (right) or z x a (left), in the ground plane.
void set_look_direction(Track& t) {
  if (t.look_side == LookSide::right) {
    t.cross_x = t.along_y;
    t.cross_y = -t.along_x;
  } else {
    t.cross_x = -t.along_y;
    t.cross_y = t.along_x;
  }
}
}  // namespace

Track resolve_track(const TrackSpec& spec, const Scene& scene, const std::string& source_file) {
  if (spec.geo) {  // latitude/longitude: into scene coordinates (ris/sensor/geo_track.h)
    return resolve_track(scene_track_from_geo(spec, scene, source_file), scene, source_file);
  }
  if (!(spec.altitude_m > 0.0) || !std::isfinite(spec.altitude_m)) {
    throw InputError(source_file, "altitude",
                     fmt::format("expected a positive altitude, got {} m", spec.altitude_m));
  }
  Track t;
  t.altitude_m = spec.altitude_m;
  t.look_side = spec.look_side;

  if (spec.kind == TrackSpec::Kind::endpoints) {
    const double dx = spec.end_x_m - spec.start_x_m;
    const double dy = spec.end_y_m - spec.start_y_m;
    const double len = std::hypot(dx, dy);
    if (!(len > 0.0)) throw InputError(source_file, "track", "track start and end coincide");
    t.start_x_m = spec.start_x_m;
    t.start_y_m = spec.start_y_m;
    t.along_x = dx / len;
    t.along_y = dy / len;
    t.length_m = len;
    set_look_direction(t);
    return t;
  }

  // Heading clockwise from north: a = (sin h, cos h).
  t.along_x = std::sin(spec.heading_rad);
  t.along_y = std::cos(spec.heading_rad);
  set_look_direction(t);
  const double x0 = scene.origin_x_m;
  const double y0 = scene.origin_y_m;
  const double x1 = x0 + scene.cols * scene.dx_m;
  const double y1 = y0 - scene.rows * scene.dy_m;
  const std::array<std::pair<double, double>, 4> corners{{{x0, y0}, {x1, y0}, {x0, y1}, {x1, y1}}};
  const double cx = 0.5 * (x0 + x1);
  const double cy = 0.5 * (y0 + y1);
  double s_min = std::numeric_limits<double>::infinity(), s_max = -s_min, u_min = s_min;
  for (const auto& [x, y] : corners) {
    const double s = (x - cx) * t.along_x + (y - cy) * t.along_y;
    const double u = (x - cx) * t.cross_x + (y - cy) * t.cross_y;
    s_min = std::min(s_min, s);
    s_max = std::max(s_max, s);
    u_min = std::min(u_min, u);
  }
  const double u_track = u_min - spec.near_edge_ground_m;
  t.start_x_m = cx + s_min * t.along_x + u_track * t.cross_x;
  t.start_y_m = cy + s_min * t.along_y + u_track * t.cross_y;
  t.length_m = s_max - s_min;
  return t;
}

}  // namespace ris
