// A closed-form anchor for geometry on geographic (EPSG:4326) DEMs, shared
// by src/geometry/geographic_anchor_test.cpp (ris topo) and
// src/sim/modes/acquisition_geographic_test.cpp (an acquisition run): an
// airborne flight line over latitude L, and a latitude/longitude GeoTIFF of
// a plane of known slope and aspect around the scene centre, written with
// GDAL and read back as ris reads any DEM.
//
// The plane is a plane in the centre's east-north-up frame: a posting at
// (lat, lon) has the height h = -tan(slope) (d . w), d its position on the
// ellipsoid (height 0) less the centre's, w = sin(A) east + cos(A) north of
// the centre (A the aspect: the azimuth the slope faces, downhill). Its
// normal at any point follows in closed form from the derivative of d with
// (lat, lon), N(lat) cos(lat) east and M(lat) north per radian at height 0,
// against the point's own east and north, (N + h) cos(lat) and M + h per
// radian at its height (facet_normal below), so the anchor holds the frame's
// rotation from the centre to the point exactly. The look vector: from the
// ground point to the sensor at the line's zero-Doppler time.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <cpl_conv.h>
#include <ogr_spatialref.h>

#include "ris/geometry/terrain_profile.h"
#include "ris/geometry/topo.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/io/raster_io.h"
#include "ris/sensor/acquisition.h"
#include "ris/util/ellipsoid.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris::test {

// An L-band airborne SAR flying north at 12.5 km over latitude lat_deg,
// longitude 10 deg, looking left (west), on a 40-line grid (880 m along
// track) of `bins` bins of 12.5 m from 16 km: 60 bins see incidence about
// 38.6-41.7 deg.
inline Acquisition plane_acquisition(const std::filesystem::path& dir, double lat_deg,
                                     int bins = 60) {
  const std::filesystem::path p = dir / "flight.toml";
  write_file(p,
             "[acquisition]\nmission = \"geographic anchor\"\n"
             "epoch = \"2024-06-01T10:00:00\"\nlook_side = \"left\"\n"
             "frequency = \"1.243 GHz\"\npolarisation = \"HH\"\n"
             "[grid]\nfirst_line_time = \"0 s\"\nline_interval = \"100 ms\"\nlines = 40\n"
             "near_range = \"16 km\"\nrange_spacing = \"12.5 m\"\nbins = " +
                 std::to_string(bins) +
                 "\n"
                 "[orbit]\nkind = \"flight_line\"\nlatitude = \"" +
                 std::to_string(lat_deg) +
                 " deg\"\nlongitude = \"10 deg\"\n"
                 "height = \"12.5 km\"\nheading = \"0 deg\"\nspeed = \"220 m/s\"\n");
  return read_acquisition(p);
}

struct GeographicPlane {
  Ellipsoid e = Ellipsoid::wgs84();
  double lat_c = 0.0, lon_c = 0.0;  // the scene centre (radians), height 0
  Vec3 centre;                      // its ECEF position
  Vec3 w;                           // the facing direction A in the centre's frame
  double tan_slope = 0.0;

  GeographicPlane(const Acquisition& a, double slope_deg, double aspect_deg) {
    const LatLonBox box = grid_corner_box(a, 0.0);
    lat_c = 0.5 * (box.lat_min_rad + box.lat_max_rad);
    lon_c = 0.5 * (box.lon_min_rad + box.lon_max_rad);
    centre = e.to_ecef({lat_c, lon_c, 0.0});
    const EnuBasis b = Ellipsoid::enu(lat_c, lon_c);
    const double A = deg_to_rad(aspect_deg);
    w = b.east * std::sin(A) + b.north * std::cos(A);
    tan_slope = std::tan(deg_to_rad(slope_deg));
  }
  double height_m(double lat, double lon) const {
    return -tan_slope * (e.to_ecef({lat, lon, 0.0}) - centre).dot(w);
  }
  // The surface's unit normal at (lat, lon) (ECEF), in closed form.
  Vec3 facet_normal(double lat, double lon) const {
    const EnuBasis b = Ellipsoid::enu(lat, lon);
    const double h = height_m(lat, lon);
    const double n_lat = e.prime_vertical_radius_m(lat), m_lat = e.meridional_radius_m(lat);
    const double g_east = -tan_slope * b.east.dot(w) * n_lat / (n_lat + h);
    const double g_north = -tan_slope * b.north.dot(w) * m_lat / (m_lat + h);
    return (b.up - b.east * g_east - b.north * g_north).normalized();
  }

  // A 1 arc-second (both axes) EPSG:4326 GeoTIFF covering the grid's corner
  // box with a margin of pad_deg north and south (pad_deg / cos(lat) east
  // and west), read back with read_ellipsoidal_dem.
  EllipsoidalDem write_dem(const Acquisition& a, const std::filesystem::path& path,
                           double pad_deg) const {
    const LatLonBox box = grid_corner_box(a, 0.0);
    const double step = 1.0 / 3600.0;
    const double pad_lon = pad_deg / std::cos(lat_c);
    const double lat_top = rad_to_deg(box.lat_max_rad) + pad_deg;
    const double lon_left = rad_to_deg(box.lon_min_rad) - pad_lon;
    const int rows =
        static_cast<int>((rad_to_deg(box.lat_max_rad - box.lat_min_rad) + 2 * pad_deg) / step) + 1;
    const int cols =
        static_cast<int>((rad_to_deg(box.lon_max_rad - box.lon_min_rad) + 2 * pad_lon) / step) + 1;
    std::vector<float> h(static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols));
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c)
        h[static_cast<std::size_t>(r) * cols + c] = static_cast<float>(
            height_m(deg_to_rad(lat_top - r * step), deg_to_rad(lon_left + c * step)));
    OGRSpatialReference srs;
    srs.importFromEPSG(4326);
    char* wkt = nullptr;
    srs.exportToWkt(&wkt);
    const Georef g{{lon_left - 0.5 * step, step, 0.0, lat_top + 0.5 * step, 0.0, -step}, wkt};
    CPLFree(wkt);
    write_geotiff<float>(path, h.data(), cols, rows, &g);
    return read_ellipsoidal_dem(path);
  }

  // The closed form at a ground point seen from the sensor at line time t_s.
  struct Expected {
    double local_incidence_deg = 0.0;
    std::uint8_t mask = 0;  // TopoMask bits of an infinite plane
    double range_m = 0.0;   // from the sensor to the ground point
  };
  Expected expected(const Acquisition& a, double t_s, double lat, double lon) const {
    const OrbitState s = a.orbit.interpolate(t_s);
    const Vec3 x = e.to_ecef({lat, lon, height_m(lat, lon)});
    const Vec3 to_sensor = s.position_m - x;
    const Vec3 l = to_sensor.normalized(), n = facet_normal(lat, lon);
    Expected out;
    out.range_m = to_sensor.norm();
    out.local_incidence_deg = rad_to_deg(std::acos(std::clamp(n.dot(l), -1.0, 1.0)));
    // In the zero-Doppler plane (normal v, the velocity): the plane's trace
    // t = v x n, oriented away from the sensor on the ground; its slant
    // range falls along t (layover) when l . t > 0, and the facet faces
    // away (shadow, on an infinite plane) when n . l < 0.
    const Vec3 v = s.velocity_m_s.normalized();
    Vec3 t = v.cross(n);
    const Vec3 up = Ellipsoid::normal(lat, lon);
    const Vec3 away = (x - s.position_m) - up * (x - s.position_m).dot(up);
    if (t.dot(away) < 0.0) t = t * -1.0;
    if (l.dot(t) > 0.0) out.mask |= kMaskLayover;
    if (n.dot(l) < 0.0) out.mask |= kMaskShadow;
    return out;
  }
};

}  // namespace ris::test
