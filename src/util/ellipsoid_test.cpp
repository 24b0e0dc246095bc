#include "ris/util/ellipsoid.h"

#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "ris/util/units.h"

namespace ris {
namespace {

const Ellipsoid kWgs = Ellipsoid::wgs84();

TEST(Ellipsoid, AxesAndSpecialPoints) {
  EXPECT_NEAR(kWgs.semi_minor_m(), 6356752.314245, 1e-6);  // NIMA TR8350.2 table 3.1
  const Vec3 eq = kWgs.to_ecef({0.0, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(eq.x, 6378137.0);
  const Vec3 pole = kWgs.to_ecef({deg_to_rad(90.0), 0.0, 100.0});
  EXPECT_NEAR(pole.z, 6356752.314245 + 100.0, 1e-6);
  EXPECT_NEAR(pole.x, 0.0, 1e-6);
  const Ellipsoid s1 = Ellipsoid::from_axes(6378137.0, 6356752.314245);
  EXPECT_NEAR(s1.e2(), kWgs.e2(), 1e-12);
}

// Round trip geodetic -> ECEF -> geodetic from the sea floor to 1000 km up.
TEST(Ellipsoid, RoundTripWithinMicrometres) {
  std::mt19937_64 rng(15);
  std::uniform_real_distribution<double> lat(-89.9, 89.9), lon(-180.0, 180.0), h(-10e3, 1000e3);
  double worst_m = 0.0;
  for (int i = 0; i < 10000; ++i) {
    const Geodetic g{deg_to_rad(lat(rng)), deg_to_rad(lon(rng)), h(rng)};
    const Geodetic b = kWgs.to_geodetic(kWgs.to_ecef(g));
    const double dn = (b.lat_rad - g.lat_rad) * kWgs.meridional_radius_m(g.lat_rad);
    const double de =
        (b.lon_rad - g.lon_rad) * kWgs.prime_vertical_radius_m(g.lat_rad) * std::cos(g.lat_rad);
    worst_m = std::max({worst_m, std::abs(dn), std::abs(de), std::abs(b.height_m - g.height_m)});
  }
  std::printf("ellipsoid round trip: %.3g m\n", worst_m);
  EXPECT_LT(worst_m, 2e-8);  // measured 3.6e-9 m
}

// Against PROJ (through GDAL's OGR): EPSG:4979 (3-D WGS 84) -> EPSG:4978 (ECEF).
TEST(Ellipsoid, AgreesWithProj) {
  OGRSpatialReference geo, ecef;
  geo.importFromEPSG(4979);
  ecef.importFromEPSG(4978);
  geo.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  ecef.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&geo, &ecef));
  ASSERT_TRUE(ct);
  const double pts[][3] = {{-97.8, 49.5, 240.0},
                           {12.5, 42.0, 48.6},
                           {-118.4, 34.2, 12000.0},
                           {150.0, -60.0, 700e3},
                           {0.0, 0.0, 0.0}};
  for (const auto& p : pts) {
    double x = p[0], y = p[1], z = p[2];
    ASSERT_TRUE(ct->Transform(1, &x, &y, &z));
    const Vec3 mine = kWgs.to_ecef({deg_to_rad(p[1]), deg_to_rad(p[0]), p[2]});
    EXPECT_NEAR(mine.x, x, 1e-6);
    EXPECT_NEAR(mine.y, y, 1e-6);
    EXPECT_NEAR(mine.z, z, 1e-6);
  }
}

TEST(Ellipsoid, EnuIsOrthonormalAndUpIsTheNormal) {
  const double lat = deg_to_rad(41.9), lon = deg_to_rad(12.5);
  const EnuBasis b = Ellipsoid::enu(lat, lon);
  EXPECT_NEAR(b.east.dot(b.north), 0.0, 1e-15);
  EXPECT_NEAR(b.east.cross(b.north).dot(b.up), 1.0, 1e-15);
  // Up is perpendicular to the ellipsoid: a small step north along the
  // surface is perpendicular to it.
  const Vec3 p0 = kWgs.to_ecef({lat, lon, 0.0});
  const Vec3 p1 = kWgs.to_ecef({lat + 1e-7, lon, 0.0});
  EXPECT_NEAR((p1 - p0).normalized().dot(b.up), 0.0, 1e-6);
}

}  // namespace
}  // namespace ris
