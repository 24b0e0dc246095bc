#include "ris/sensor/geo_track.h"

#include <cpl_string.h>
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>

#include "ris/scene/geo_frame.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/track.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

RadarParams radar_with_track(const std::string& track_lines) {
  const std::string text = R"(name = "t"
mode = "slar"
frequency = "9.4 GHz"
polarisation = "HH"
pulse_width = "0.1 us"
near_range = "12000 m"
far_range = "20000 m"
azimuth_beamwidth = "1 deg"
[track]
altitude = "6000 m"
)" + track_lines;
  toml::table doc = toml::parse(text);
  return radar_from_toml(doc, "radar.toml");
}

// A flat 200 x 300 scene of 20 m cells at 100 m in UTM 33N near Rome, west
// of the zone's central meridian (15 E), where grid and true north differ.
Scene utm_scene() {
  Scene s = Scene::flat(200, 300, 20.0, 100.0f, 1);
  OGRSpatialReference srs;
  srs.importFromEPSG(32633);
  char* wkt = nullptr;
  srs.exportToWkt(&wkt);
  s.crs_wkt = wkt;
  CPLFree(wkt);
  s.origin_x_m = 290000.0;
  s.origin_y_m = 4654000.0;
  return s;
}

TEST(GeoTrack, EndpointsInLatLonAreProjectedIntoTheScene) {
  RadarParams r = radar_with_track("start_latlon = [41.95, 12.40]\nend_latlon = [42.05, 12.41]\n");
  ASSERT_TRUE(r.track.geo.has_value());
  Scene s = utm_scene();
  Track t = resolve_track(r.track, s, r.source_file);
  GeoFrame frame(s.crs_wkt, "test");
  auto [x0, y0] = frame.scene_from_lonlat(12.40, 41.95);
  auto [x1, y1] = frame.scene_from_lonlat(12.41, 42.05);
  EXPECT_NEAR(t.start_x_m, x0, 1e-6);
  EXPECT_NEAR(t.start_y_m, y0, 1e-6);
  EXPECT_NEAR(t.length_m, std::hypot(x1 - x0, y1 - y0), 1e-6);
  EXPECT_NEAR(t.along_x, (x1 - x0) / t.length_m, 1e-12);
  EXPECT_DOUBLE_EQ(t.altitude_m, 6000.0);
  // And back: the track's start is the given latitude/longitude within 1 cm.
  auto [lon, lat] = frame.lonlat_from_scene(t.start_x_m, t.start_y_m);
  EXPECT_NEAR(lat, 41.95, 1e-7);
  EXPECT_NEAR(lon, 12.40, 1e-7);
}

TEST(GeoTrack, HeadingAndNearRangePointPutThatPointAtNearRange) {
  for (const char* heading : {"0 deg", "90 deg", "200 deg"}) {
    for (const char* side : {"right", "left"}) {
      RadarParams r = radar_with_track(
          fmt::format("look_side = \"{}\"\nheading = \"{}\"\nnear_range_point = [42.0, 12.49]\n",
                      side, heading));
      Scene s = utm_scene();
      Track t = resolve_track(r.track, s, r.source_file);
      GeoFrame frame(s.crs_wkt, "test");
      auto [px, py] = frame.scene_from_lonlat(12.49, 42.0);
      // The point is on the look side at the ground distance where the slant
      // range is R_near over terrain 100 m high.
      auto [sp, up] = t.along_cross(px, py);
      EXPECT_NEAR(std::hypot(up, 6000.0 - 100.0), 12000.0, 1e-6) << heading << side;
      EXPECT_GT(up, 0.0);
      // The heading is true: along the meridian (or across it) through the
      // point, whatever the grid convergence.
      auto [sx, sy] = frame.scene_from_lonlat(12.49, 41.9999);
      auto [nx, ny] = frame.scene_from_lonlat(12.49, 42.0001);
      const double north = std::atan2(nx - sx, ny - sy);
      // West of the central meridian true north leans east of grid north by
      // the convergence atan(tan(15 - 12.49 deg) sin 42 deg) = 1.680 deg.
      EXPECT_NEAR(north, std::atan(std::tan(deg_to_rad(2.51)) * std::sin(deg_to_rad(42.0))),
                  deg_to_rad(0.01));
      const double a = std::atan2(t.along_x, t.along_y);
      const double want = north + deg_to_rad(std::stod(heading));
      EXPECT_NEAR(std::remainder(a - want, 2 * kPi), 0.0, 1e-8) << heading;
      // The track spans the scene along its heading.
      for (auto [x, y] : {s.world_from_grid(0, 0), s.world_from_grid(s.cols, s.rows)}) {
        auto [sc, uc] = t.along_cross(x, y);
        EXPECT_GE(sc, -1e-6);
        EXPECT_LE(sc, t.length_m + 1e-6);
      }
    }
  }
}

TEST(GeoTrack, BadGeographicTracksAreInputErrors) {
  auto expect_key = [](const std::string& lines, const std::string& key) {
    try {
      radar_with_track(lines);
      FAIL() << "expected an InputError for " << key;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  };
  expect_key("start_latlon = [41.9, 12.4]\nend_latlon = [42.0, 12.4]\nstart = [0, 0]\n", "start");
  expect_key("start_latlon = [95.0, 12.4]\nend_latlon = [42.0, 12.4]\n", "start_latlon");
  expect_key("start_latlon = [42.0, 12.4]\nend_latlon = [42.0, 12.4]\n", "end_latlon");
  expect_key("near_range_point = [42.0]\n", "near_range_point");
  expect_key("near_range_point = [42.0, 12.4]\nnear_edge_distance = 100\n", "near_edge_distance");
  expect_key("near_range_point = [42.0, 12.4]\nheadin = 3\n", "headin");

  // A scene without CRS cannot take a geographic track.
  RadarParams r = radar_with_track("near_range_point = [42.0, 12.49]\n");
  Scene local = Scene::flat(10, 10, 20.0, 0.0f, 1);
  EXPECT_THROW(resolve_track(r.track, local, r.source_file), InputError);
}

}  // namespace
}  // namespace ris
