// Flight tracks given in geographic terms (the seed's RADAR(2-5) as
// latitude/longitude; docs/radar-format.md, [track]):
//
//   [track]
//   altitude = "12000 m"                # above the scene datum, as always
//   look_side = "right"
//   start_latlon = [42.00, 12.40]       # degrees: latitude, longitude
//   end_latlon = [42.10, 12.40]
//
// or a heading and the ground point seen at near range:
//
//   heading = "0 deg"                   # true heading, clockwise from north
//   near_range_point = [42.05, 12.45]   # the swath's near edge passes here
//
// The parser (ris/sensor/radar_config.h) hands [track] to parse_geo_track
// first; resolve_track (ris/sensor/track.h) hands a geographic spec to
// scene_track_from_geo, which converts it into a scene-coordinate endpoints
// spec with PROJ (GeoFrame): the track is the straight line between the
// projected points in the scene frame (over a few hundred kilometres of UTM
// the geodesic departs from it by well under a cell). A heading is turned
// into grid heading with the meridian convergence at the point. For
// near_range_point the track runs at the ground distance
// u0 = sqrt(R_near^2 - (H - h)^2) from the point (h: the scene's elevation
// there, 0 outside the scene) on the side opposite the look direction, and
// spans the whole scene along its heading, as heading + near_edge_distance
// does.
//
// Example:
//   ris::TrackSpec scene_spec = ris::scene_track_from_geo(radar.track, scene, radar.source_file);
#pragma once

#include <array>
#include <string>

#include "ris/io/config_table.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"

namespace ris {

// [latitude, longitude] in degrees (plain numbers or "<n> deg") from `key`,
// range-checked (InputError naming the key otherwise).
std::array<double, 2> parse_lat_lon(ConfigTable& t, const std::string& key);

// Reads start_latlon/end_latlon, or near_range_point (with heading), from the
// [track] table into spec.geo and finishes the table; returns false (reading
// nothing) when the table has none of these keys. Mixing them with start,
// end or near_edge_distance is an InputError.
bool parse_geo_track(ConfigTable& track, TrackSpec& spec);

// The scene-coordinate endpoints spec of a geographic spec (spec.geo set).
// InputError (naming source_file and the key) when the scene has no CRS or a
// point cannot be placed, or the near slant range does not reach the ground.
TrackSpec scene_track_from_geo(const TrackSpec& spec, const Scene& scene,
                               const std::string& source_file);

}  // namespace ris
