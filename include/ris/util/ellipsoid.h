// The Earth's reference ellipsoid (WGS 84 by default) and the conversions
// between geodetic coordinates (latitude, longitude, height above the
// ellipsoid) and Earth-centred, Earth-fixed Cartesian coordinates (ECEF),
// with the local east-north-up frame and the ellipsoid normal.
//
// Forward (geodetic -> ECEF): the closed form of every geodesy text, e.g.
// Hofmann-Wellenhof et al., "GNSS" (2008), eq. 2.151. Inverse: Vermeille's
// exact closed form (Vermeille, H., 2002, "Direct transformation from
// geocentric coordinates to geodetic coordinates", Journal of Geodesy 76,
// 451-454), valid everywhere outside a 43 km region around the Earth's
// centre; the same method ISCE3's isce3::core::Ellipsoid::xyzToLonLat uses.
// docs/geometry.md gives the equations.
//
// Example:
//   const ris::Ellipsoid wgs = ris::Ellipsoid::wgs84();
//   ris::Vec3 p = wgs.to_ecef({ris::deg_to_rad(49.5), ris::deg_to_rad(-97.8), 240.0});
//   ris::Geodetic g = wgs.to_geodetic(p);  // back to 49.5 N, 97.8 W, 240 m
#pragma once

#include "ris/util/vec3.h"

namespace ris {

// Geodetic coordinates: latitude and longitude in radians, height above the
// ellipsoid in metres.
struct Geodetic {
  double lat_rad = 0.0;
  double lon_rad = 0.0;
  double height_m = 0.0;
};

// The local east, north and up unit vectors (up = the ellipsoid normal) at a
// geodetic latitude and longitude, in ECEF.
struct EnuBasis {
  Vec3 east, north, up;
};

class Ellipsoid {
 public:
  // semi_major_m: equatorial radius a; e2: first eccentricity squared.
  constexpr Ellipsoid(double semi_major_m, double e2) : a_(semi_major_m), e2_(e2) {}
  // WGS 84: a = 6378137 m, 1/f = 298.257223563 (NIMA TR8350.2, 2000).
  static constexpr Ellipsoid wgs84() {
    constexpr double f = 1.0 / 298.257223563;
    return Ellipsoid(6378137.0, f * (2.0 - f));
  }
  // From the semi-major and semi-minor axes (as Sentinel-1 annotations give).
  static Ellipsoid from_axes(double semi_major_m, double semi_minor_m);

  double semi_major_m() const { return a_; }
  double e2() const { return e2_; }
  double semi_minor_m() const;

  // Radius of curvature in the prime vertical, N(lat) = a / sqrt(1 - e2 sin^2 lat).
  double prime_vertical_radius_m(double lat_rad) const;
  // Meridional radius of curvature, M(lat) = a (1 - e2) / (1 - e2 sin^2 lat)^1.5.
  double meridional_radius_m(double lat_rad) const;

  Vec3 to_ecef(const Geodetic& g) const;
  Geodetic to_geodetic(const Vec3& ecef_m) const;

  // Unit outward normal to the ellipsoid (the "up" of the local frame).
  static Vec3 normal(double lat_rad, double lon_rad);
  static EnuBasis enu(double lat_rad, double lon_rad);

 private:
  double a_;
  double e2_;
};

}  // namespace ris
