#include "ris/scene/geo_frame.h"
#include "build_paths.h"

#include <cpl_string.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>

#include "ris/scene/dem_import.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

std::string utm_wkt(int epsg) {
  OGRSpatialReference srs;
  srs.importFromEPSG(epsg);
  char* text = nullptr;
  srs.exportToWkt(&text);
  std::string out = text;
  CPLFree(text);
  return out;
}

// Metres between two nearby lon/lat points (local spherical approximation,
// good to far better than a centimetre over centimetres).
double ground_distance_m(double lon0, double lat0, double lon1, double lat1) {
  const double r = 6371000.0;
  const double dx = deg_to_rad(lon1 - lon0) * std::cos(deg_to_rad(lat0)) * r;
  const double dy = deg_to_rad(lat1 - lat0) * r;
  return std::hypot(dx, dy);
}

TEST(GeoFrame, LatLonSceneLatLonRoundTripsWithinOneCentimetre) {
  // The scene frame of the imported Rome DEM, and points across and beyond it.
  ImportedDem dem = import_dem(std::string(ris::test::test_data_dir()) + "/dem/Rome-30m-DEM.tif");
  GeoFrame frame(dem.scene.crs_wkt, "Rome");
  EXPECT_EQ(frame.geographic_crs_name(), "WGS 84");
  EXPECT_EQ(frame.scene_crs_name(), "WGS 84 / UTM zone 33N");
  double worst_m = 0.0;
  for (double lat = 41.5; lat <= 42.5; lat += 0.0371) {
    for (double lon = 12.0; lon <= 13.0; lon += 0.0433) {
      auto [x, y] = frame.scene_from_lonlat(lon, lat);
      auto [lon2, lat2] = frame.lonlat_from_scene(x, y);
      worst_m = std::max(worst_m, ground_distance_m(lon, lat, lon2, lat2));
      // And scene -> lat/lon -> scene, in metres directly.
      auto [x2, y2] = frame.scene_from_lonlat(lon2, lat2);
      worst_m = std::max(worst_m, std::hypot(x2 - x, y2 - y));
    }
  }
  EXPECT_LT(worst_m, 0.01);
}

TEST(GeoFrame, CentralMeridianMatchesTheMeridianArc) {
  // On the central meridian (15 E for zone 33) UTM gives E = 500 000 m and
  // N = k0 M(phi), with M the WGS 84 meridian arc (Snyder 1987, eq. 3-21).
  GeoFrame frame(utm_wkt(32633), "test");
  const double a = 6378137.0, f = 1.0 / 298.257223563, e2 = f * (2 - f);
  const double e4 = e2 * e2, e6 = e4 * e2;
  for (double lat : {0.0, 10.0, 42.0, 60.0}) {
    const double phi = deg_to_rad(lat);
    const double m = a * ((1 - e2 / 4 - 3 * e4 / 64 - 5 * e6 / 256) * phi -
                          (3 * e2 / 8 + 3 * e4 / 32 + 45 * e6 / 1024) * std::sin(2 * phi) +
                          (15 * e4 / 256 + 45 * e6 / 1024) * std::sin(4 * phi) -
                          (35 * e6 / 3072) * std::sin(6 * phi));
    auto [x, y] = frame.scene_from_lonlat(15.0, lat);
    EXPECT_NEAR(x, 500000.0, 1e-6) << lat;
    EXPECT_NEAR(y, 0.9996 * m, 0.01) << lat;
  }
}

TEST(GeoFrame, NonMetricOrMissingCrsIsRefused) {
  EXPECT_THROW(GeoFrame("", "scene.tif"), InputError);
  EXPECT_THROW(GeoFrame(utm_wkt(4326), "scene.tif"), InputError);
  EXPECT_THROW(GeoFrame("not wkt", "scene.tif"), InputError);
  GeoFrame frame(utm_wkt(32633), "scene.tif");
  EXPECT_THROW(frame.scene_from_lonlat(12.0, 95.0), InputError);
}

}  // namespace
}  // namespace ris
