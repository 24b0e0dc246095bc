#include "ris/sensor/geo_track.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "ris/scene/geo_frame.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

// [lat, lon] in degrees (numbers, or strings with "deg").
}  // namespace

std::array<double, 2> parse_lat_lon(ConfigTable& t, const std::string& key) {
  const std::vector<double> v = t.get_quantity_array(key, Quantity::angle);
  if (v.size() != 2) {
    t.fail(key,
           fmt::format("expected [latitude, longitude] in degrees (2 values), got {}", v.size()));
  }
  const double lat = rad_to_deg(v[0]), lon = rad_to_deg(v[1]);
  if (!(std::abs(lat) <= 90.0) || !(std::abs(lon) <= 180.0)) {
    t.fail(key, fmt::format("latitude {} deg or longitude {} deg out of range", lat, lon));
  }
  return {lat, lon};
}

bool parse_geo_track(ConfigTable& t, TrackSpec& spec) {
  const bool endpoints = t.has("start_latlon") || t.has("end_latlon");
  const bool point = t.has("near_range_point");
  if (!endpoints && !point) return false;
  for (const char* other : {"start", "end", "near_edge_distance"}) {
    if (t.has(other)) {
      t.fail(other, fmt::format("give the track either in latitude/longitude or in scene "
                                "coordinates, not both ({} with {})",
                                other, endpoints ? "start_latlon/end_latlon" : "near_range_point"));
    }
  }
  if (endpoints && point) {
    t.fail("near_range_point",
           "give either start_latlon and end_latlon, or heading and near_range_point");
  }
  GeoTrackSpec g;
  if (endpoints) {
    g.kind = GeoTrackSpec::Kind::endpoints;
    const auto a = parse_lat_lon(t, "start_latlon");
    const auto b = parse_lat_lon(t, "end_latlon");
    if (a == b) t.fail("end_latlon", "track start and end coincide");
    g.start_lat_deg = a[0];
    g.start_lon_deg = a[1];
    g.end_lat_deg = b[0];
    g.end_lon_deg = b[1];
  } else {
    g.kind = GeoTrackSpec::Kind::heading_near_range_point;
    const auto p = parse_lat_lon(t, "near_range_point");
    g.point_lat_deg = p[0];
    g.point_lon_deg = p[1];
    g.heading_rad = t.get_quantity_or("heading", Quantity::angle, 0.0);
    if (!std::isfinite(g.heading_rad)) t.fail("heading", "expected a finite angle");
  }
  spec.geo = g;
  t.finish();
  return true;
}

TrackSpec scene_track_from_geo(const TrackSpec& spec, const Scene& scene,
                               const std::string& source_file) {
  RIS_CHECK(spec.geo.has_value());
  const GeoTrackSpec& g = *spec.geo;
  TrackSpec out = spec;
  out.geo.reset();
  out.kind = TrackSpec::Kind::endpoints;
  const std::string key =
      g.kind == GeoTrackSpec::Kind::endpoints ? "start_latlon" : "near_range_point";
  if (scene.crs_wkt.empty()) {
    throw InputError(source_file, key,
                     "the track is in latitude/longitude but the scene has no CRS (import a "
                     "DEM with ris scene import, or place a fractal scene with --centre)");
  }
  GeoFrame frame(scene.crs_wkt, source_file);

  if (g.kind == GeoTrackSpec::Kind::endpoints) {
    std::tie(out.start_x_m, out.start_y_m) =
        frame.scene_from_lonlat(g.start_lon_deg, g.start_lat_deg);
    std::tie(out.end_x_m, out.end_y_m) = frame.scene_from_lonlat(g.end_lon_deg, g.end_lat_deg);
    return out;
  }

  // Grid heading = true heading + meridian convergence (the angle of true
  // north clockwise from the scene's +y at the point).
  const auto [px, py] = frame.scene_from_lonlat(g.point_lon_deg, g.point_lat_deg);
  // The meridian's direction at the point by a central difference of +-1e-5
  // deg (about 1 m) of latitude.
  const double dlat = std::min(1e-5, 90.0 - std::abs(g.point_lat_deg));
  const auto [sx, sy] = frame.scene_from_lonlat(g.point_lon_deg, g.point_lat_deg - dlat);
  const auto [nx, ny] = frame.scene_from_lonlat(g.point_lon_deg, g.point_lat_deg + dlat);
  const double convergence_rad = std::atan2(nx - sx, ny - sy);
  const double grid_heading = g.heading_rad + convergence_rad;
  const double ax = std::sin(grid_heading), ay = std::cos(grid_heading);
  // Ground look direction g = a x z (right) or z x a (left), as in track.cpp.
  const double gx = spec.look_side == LookSide::right ? ay : -ay;
  const double gy = spec.look_side == LookSide::right ? -ax : ax;

  // Height of the point: the scene's, where it has data.
  double h_m = 0.0;
  const auto [fc, fr] = scene.grid_from_world(px, py);
  const int c = static_cast<int>(std::floor(fc)), r = static_cast<int>(std::floor(fr));
  if (scene.contains(r, c) && scene.valid[scene.index(r, c)])
    h_m = scene.elevation_m[scene.index(r, c)];
  const double dh = spec.altitude_m - h_m;
  if (!(g.near_slant_range_m > dh)) {
    throw InputError(source_file, "near_range_point",
                     fmt::format("the near slant range ({:.1f} m) does not reach the ground at the "
                                 "point ({:.1f} m below the radar)",
                                 g.near_slant_range_m, dh));
  }
  const double u0 = std::sqrt(g.near_slant_range_m * g.near_slant_range_m - dh * dh);
  const double lx = px - u0 * gx, ly = py - u0 * gy;  // a point of the ground track

  // Span the whole scene along the heading.
  const double x0 = scene.origin_x_m, y0 = scene.origin_y_m;
  const double x1 = x0 + scene.cols * scene.dx_m, y1 = y0 - scene.rows * scene.dy_m;
  double s_min = std::numeric_limits<double>::infinity(), s_max = -s_min;
  for (const auto& [x, y] :
       {std::pair{x0, y0}, std::pair{x1, y0}, std::pair{x0, y1}, std::pair{x1, y1}}) {
    const double s = (x - lx) * ax + (y - ly) * ay;
    s_min = std::min(s_min, s);
    s_max = std::max(s_max, s);
  }
  out.start_x_m = lx + s_min * ax;
  out.start_y_m = ly + s_min * ay;
  out.end_x_m = lx + s_max * ax;
  out.end_y_m = ly + s_max * ay;
  return out;
}

}  // namespace ris
