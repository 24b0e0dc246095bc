// A straight, level flight track in scene coordinates (MODEL.md section 2).
//
// With along-track unit vector a and up z, the ground cross-track (look)
// direction is g = a x z for a right-looking radar and g = z x a for a
// left-looking one. For a ground point p: s = (p - T0) . a, u = (p - T0) . g.
//
// Example:
//   ris::Track t = ris::resolve_track(radar.track, scene, radar.source_file);
//   auto [s_m, u_m] = t.along_cross(x_m, y_m);
#pragma once

#include <string>
#include <utility>

#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"

namespace ris {

struct Track {
  double start_x_m = 0.0;  // T0, ground projection of the track start
  double start_y_m = 0.0;
  double along_x = 0.0;  // a, unit along-track vector (scene x, y)
  double along_y = 1.0;
  double cross_x = 1.0;  // g, unit ground look direction
  double cross_y = 0.0;
  double length_m = 0.0;    // ground length of the track from T0
  double altitude_m = 0.0;  // H above the scene datum
  LookSide look_side = LookSide::right;

  // (s, u): along-track position and cross-track ground distance of (x, y).
  std::pair<double, double> along_cross(double x_m, double y_m) const {
    const double dx = x_m - start_x_m;
    const double dy = y_m - start_y_m;
    return {dx * along_x + dy * along_y, dx * cross_x + dy * cross_y};
  }
  // Scene (x, y) of the ground point at (s, u).
  std::pair<double, double> world_from_along_cross(double s_m, double u_m) const {
    return {start_x_m + s_m * along_x + u_m * cross_x, start_y_m + s_m * along_y + u_m * cross_y};
  }
};

// Builds the track from its specification. For heading_near_edge the track
// runs along the heading past the whole scene (from the scene's first to last
// along-track extent), at the given ground distance from the scene's nearest
// corner. Throws InputError (naming source_file) for a zero-length track or a
// non-positive altitude.
Track resolve_track(const TrackSpec& spec, const Scene& scene, const std::string& source_file);

}  // namespace ris
