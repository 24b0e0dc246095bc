#include "ris/sensor/generated_orbit.h"

#include <cmath>
#include <vector>

namespace ris {
namespace {

std::vector<double> sample_times(double t0_s, double t1_s, double step_s) {
  const double a = std::floor(t0_s / step_s), b = std::ceil(t1_s / step_s);
  std::vector<double> t;
  for (double k = a; k <= b; k += 1.0) t.push_back(k * step_s);
  return t;
}

}  // namespace

// Inertial position and velocity on the circle (Vallado, "Fundamentals of
// Astrodynamics", 4th ed., algorithm 10 with e = 0), then the rotation into
// the Earth-fixed frame: x_e = Rz(-w t) x_i, v_e = Rz(-w t) v_i - w x x_e.
Orbit make_circular_orbit(const CircularOrbitParams& p, const Ellipsoid& e, UtcTime epoch,
                          double t0_s, double t1_s, double step_s) {
  const double r = e.semi_major_m() + p.altitude_m;
  const double n = std::sqrt(kEarthGm_m3_s2 / (r * r * r));
  const double ci = std::cos(p.inclination_rad), si = std::sin(p.inclination_rad);
  const double co = std::cos(p.ascending_node_lon_rad), so = std::sin(p.ascending_node_lon_rad);
  std::vector<StateVector> sv;
  for (double t : sample_times(t0_s, t1_s, step_s)) {
    const double u = p.argument_of_latitude_rad + n * t;
    const double cu = std::cos(u), su = std::sin(u);
    const Vec3 xi{r * (cu * co - su * ci * so), r * (cu * so + su * ci * co), r * su * si};
    const Vec3 vi{r * n * (-su * co - cu * ci * so), r * n * (-su * so + cu * ci * co),
                  r * n * cu * si};
    const double th = kEarthRotation_rad_s * t;
    const double ct = std::cos(th), st = std::sin(th);
    const Vec3 xe{ct * xi.x + st * xi.y, -st * xi.x + ct * xi.y, xi.z};
    const Vec3 ve{ct * vi.x + st * vi.y + kEarthRotation_rad_s * xe.y,
                  -st * vi.x + ct * vi.y - kEarthRotation_rad_s * xe.x, vi.z};
    sv.push_back({t, xe, ve});
  }
  return Orbit(epoch, std::move(sv));
}

// The great circle from (lat1, lon1) with initial azimuth a after angular
// distance d: lat2 = asin(sin lat1 cos d + cos lat1 sin d cos a),
// lon2 = lon1 + atan2(sin a sin d cos lat1, cos d - sin lat1 sin lat2).
// Velocity by a central difference of 1 ms (error ~ 1e-9 m/s here).
Orbit make_flight_line_orbit(const FlightLineParams& p, const Ellipsoid& e, UtcTime epoch,
                             double t0_s, double t1_s, double step_s) {
  // The speed is the platform's, at its height: angular rate speed / (R + h).
  const double radius_m =
      std::sqrt(e.meridional_radius_m(p.lat_rad) * e.prime_vertical_radius_m(p.lat_rad)) +
      p.height_m;
  const auto at = [&](double t) {
    const double d = p.speed_m_s * t / radius_m;
    const double s1 = std::sin(p.lat_rad), c1 = std::cos(p.lat_rad);
    const double lat2 = std::asin(s1 * std::cos(d) + c1 * std::sin(d) * std::cos(p.heading_rad));
    const double lon2 = p.lon_rad + std::atan2(std::sin(p.heading_rad) * std::sin(d) * c1,
                                               std::cos(d) - s1 * std::sin(lat2));
    return e.to_ecef({lat2, lon2, p.height_m});
  };
  constexpr double kDt = 1e-3;
  std::vector<StateVector> sv;
  for (double t : sample_times(t0_s, t1_s, step_s)) {
    sv.push_back({t, at(t), (at(t + kDt) - at(t - kDt)) * (0.5 / kDt)});
  }
  return Orbit(epoch, std::move(sv));
}

}  // namespace ris
