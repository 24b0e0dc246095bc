#include "ris/util/ellipsoid.h"

#include <cmath>

namespace ris {

Ellipsoid Ellipsoid::from_axes(double semi_major_m, double semi_minor_m) {
  const double r = semi_minor_m / semi_major_m;
  return Ellipsoid(semi_major_m, 1.0 - r * r);
}

double Ellipsoid::semi_minor_m() const {
  return a_ * std::sqrt(1.0 - e2_);
}

double Ellipsoid::prime_vertical_radius_m(double lat_rad) const {
  const double s = std::sin(lat_rad);
  return a_ / std::sqrt(1.0 - e2_ * s * s);
}

double Ellipsoid::meridional_radius_m(double lat_rad) const {
  const double s = std::sin(lat_rad);
  const double w = 1.0 - e2_ * s * s;
  return a_ * (1.0 - e2_) / (w * std::sqrt(w));
}

// X = (N + h) cos(lat) cos(lon), Y = (N + h) cos(lat) sin(lon),
// Z = (N (1 - e2) + h) sin(lat).
Vec3 Ellipsoid::to_ecef(const Geodetic& g) const {
  const double sl = std::sin(g.lat_rad), cl = std::cos(g.lat_rad);
  const double n = a_ / std::sqrt(1.0 - e2_ * sl * sl);
  const double r = (n + g.height_m) * cl;
  return {r * std::cos(g.lon_rad), r * std::sin(g.lon_rad), (n * (1.0 - e2_) + g.height_m) * sl};
}

// Vermeille (2002), section 2: p, q, r, s, t, u, v, w, k, D in his notation.
Geodetic Ellipsoid::to_geodetic(const Vec3& e) const {
  const double a2 = a_ * a_;
  const double e4 = e2_ * e2_;
  const double rho2 = e.x * e.x + e.y * e.y;
  const double p = rho2 / a2;
  const double q = (1.0 - e2_) / a2 * e.z * e.z;
  const double r = (p + q - e4) / 6.0;
  const double s = e4 * p * q / (4.0 * r * r * r);
  const double t = std::cbrt(1.0 + s + std::sqrt(s * (2.0 + s)));
  const double u = r * (1.0 + t + 1.0 / t);
  const double v = std::sqrt(u * u + e4 * q);
  const double w = e2_ * (u + v - q) / (2.0 * v);
  const double k = std::sqrt(u + v + w * w) - w;
  const double d = k * std::sqrt(rho2) / (k + e2_);
  const double dz = std::sqrt(d * d + e.z * e.z);
  Geodetic g;
  g.lat_rad = 2.0 * std::atan2(e.z, d + dz);
  g.lon_rad = std::atan2(e.y, e.x);
  g.height_m = (k + e2_ - 1.0) / k * dz;
  return g;
}

Vec3 Ellipsoid::normal(double lat_rad, double lon_rad) {
  const double cl = std::cos(lat_rad);
  return {cl * std::cos(lon_rad), cl * std::sin(lon_rad), std::sin(lat_rad)};
}

EnuBasis Ellipsoid::enu(double lat_rad, double lon_rad) {
  const double sl = std::sin(lat_rad), cl = std::cos(lat_rad);
  const double so = std::sin(lon_rad), co = std::cos(lon_rad);
  return {{-so, co, 0.0}, {-sl * co, -sl * so, cl}, {cl * co, cl * so, sl}};
}

}  // namespace ris
