#include "ris/geometry/zero_doppler.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ris {

RadarPoint geo2rdr(const Orbit& orbit, const Vec3& x, double t_guess_s, double tol_s,
                   int max_iter) {
  RadarPoint r;
  double t = std::clamp(t_guess_s, orbit.start_s(), orbit.end_s());
  for (int i = 0; i < max_iter; ++i) {
    const OrbitState s = orbit.interpolate(t);
    const Vec3 d = x - s.position_m;
    const double f = s.velocity_m_s.dot(d);
    const double df = s.acceleration_m_s2.dot(d) - s.velocity_m_s.dot(s.velocity_m_s);
    const double dt = -f / df;
    r.iterations = i + 1;
    if (std::abs(dt) < tol_s) {
      // The last step is below the tolerance: move the sensor along its
      // velocity instead of interpolating again (error |a| dt^2 / 2 < 1e-14 m).
      t += dt;
      r.sensor_m = s.position_m + s.velocity_m_s * dt;
      r.converged = orbit.covers(t);
      r.time_s = t;
      r.slant_range_m = (x - r.sensor_m).norm();
      return r;
    }
    t = std::clamp(t + dt, orbit.start_s(), orbit.end_s());
  }
  r.time_s = t;
  r.sensor_m = orbit.interpolate(t).position_m;
  r.slant_range_m = (x - r.sensor_m).norm();
  return r;
}

double doppler_hz(const Orbit& orbit, const Vec3& x, double t_s, double wavelength_m) {
  const OrbitState s = orbit.interpolate(t_s);
  const Vec3 d = x - s.position_m;
  return 2.0 * s.velocity_m_s.dot(d) / (wavelength_m * d.norm());
}

LookAngles look_angles(const Ellipsoid& e, const Vec3& sensor_m, const Vec3& target_m) {
  const Vec3 los = (sensor_m - target_m).normalized();
  const Geodetic gt = e.to_geodetic(target_m);
  const Geodetic gs = e.to_geodetic(sensor_m);
  const auto deg = [](double c) { return std::acos(std::clamp(c, -1.0, 1.0)) * 57.29577951308232; };
  LookAngles a;
  a.incidence_deg = deg(Ellipsoid::normal(gt.lat_rad, gt.lon_rad).dot(los));
  a.incidence_geocentric_deg = deg(target_m.normalized().dot(los));
  a.look_deg = deg(Ellipsoid::normal(gs.lat_rad, gs.lon_rad).dot(los));
  return a;
}

ZeroDopplerFrame::ZeroDopplerFrame(const OrbitState& s, LookSide look, const Ellipsoid& e)
    : sensor_m(s.position_m),
      velocity_m_s(s.velocity_m_s),
      sensor_geodetic(e.to_geodetic(s.position_m)) {
  const Geodetic& g = sensor_geodetic;
  nadir_normal = Ellipsoid::normal(g.lat_rad, g.lon_rad);
  const Vec3 vhat = s.velocity_m_s.normalized();
  const Vec3 down = -nadir_normal;
  nadir = (down - vhat * down.dot(vhat)).normalized();
  side = vhat.cross(nadir) * static_cast<double>(static_cast<int>(look));
}

double ZeroDopplerFrame::look_on_sphere(double range_m, double rho_m) const {
  const double ps = sensor_m.norm();
  const double c = (ps * ps + range_m * range_m - rho_m * rho_m) / (2.0 * ps * range_m);
  return std::acos(std::clamp(c, -1.0, 1.0));
}

double ZeroDopplerFrame::range_to_ellipsoid(double look_rad, const Ellipsoid& e,
                                            double height_m) const {
  const double ia = 1.0 / (e.semi_major_m() + height_m);
  const double ib = 1.0 / (e.semi_minor_m() + height_m);
  const Vec3 u = nadir * std::cos(look_rad) + side * std::sin(look_rad);
  const Vec3 du{u.x * ia, u.y * ia, u.z * ib};
  const Vec3 dp{sensor_m.x * ia, sensor_m.y * ia, sensor_m.z * ib};
  const double qa = du.dot(du), qb = dp.dot(du), qc = dp.dot(dp) - 1.0;
  const double disc = qb * qb - qa * qc;
  if (disc < 0.0) return std::numeric_limits<double>::quiet_NaN();
  return (-qb - std::sqrt(disc)) / qa;
}

}  // namespace ris
