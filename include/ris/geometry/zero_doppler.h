// Zero-Doppler radar geometry against an orbit on the ellipsoidal Earth:
// geo2rdr (ground point -> zero-Doppler time and slant range) and rdr2geo
// (time and slant range -> ground point on a height model).
//
// geo2rdr solves f(t) = v(t) . (X - p(t)) = 0 (the target is broadside:
// zero Doppler) by Newton's method, f'(t) = a(t) . (X - p(t)) - |v(t)|^2,
// against the Hermite-interpolated orbit (ISCE3 isce3::geometry::geo2rdr
// does the same on f_D = 2 v.(X-p) / (lambda R)). rdr2geo intersects the
// circle {|X - p| = R, v . (X - p) = 0} with the surface h(X) = h_dem(lat,
// lon): X(theta) = p + R (cos theta c1 + sin theta c2), theta the look angle
// from the projected nadir c1 and c2 = the look side's direction
// (ISCE3's convention: left = +1 times v x c1), solved by a safeguarded
// secant iteration in theta (ISCE3 iterates on a local sphere instead; the
// solution is the same point). docs/geometry.md has the equations.
#pragma once

#include <cmath>
#include <limits>

#include "ris/sensor/orbit.h"
#include "ris/sensor/radar_grid.h"
#include "ris/util/ellipsoid.h"
#include "ris/util/vec3.h"

namespace ris {

struct RadarPoint {
  double time_s = 0.0;         // zero-Doppler time, s since the orbit epoch
  double slant_range_m = 0.0;  // one way
  Vec3 sensor_m;               // the sensor's position at time_s
  int iterations = 0;
  bool converged = false;
};

// Newton iteration from t_guess_s until |dt| < tol_s (at most max_iter).
// The time stays clamped to the orbit's span; a target whose zero-Doppler
// time lies outside it comes back with converged = false. No allocation.
RadarPoint geo2rdr(const Orbit& orbit, const Vec3& target_ecef_m, double t_guess_s,
                   double tol_s = 1e-9, int max_iter = 30);

// The Doppler of a target seen from the orbit at time t (Hz):
// f_D = 2 v . (X - p) / (lambda |X - p|).
double doppler_hz(const Orbit& orbit, const Vec3& target_ecef_m, double t_s, double wavelength_m);

// The angles under which a sensor sees a target (degrees): incidence to the
// ellipsoid normal at the target (ISCE's incidence layers), incidence to the
// geocentric radius (Sentinel-1 annotations' incidenceAngle), and the look
// angle at the sensor from its geodetic nadir.
struct LookAngles {
  double incidence_deg = 0.0;
  double incidence_geocentric_deg = 0.0;
  double look_deg = 0.0;
};
LookAngles look_angles(const Ellipsoid& e, const Vec3& sensor_m, const Vec3& target_m);

// The zero-Doppler plane at one azimuth time: the sensor state and the two
// unit vectors spanning the plane (c1 towards the geodetic nadir, c2 towards
// the look side). One per image line.
struct ZeroDopplerFrame {
  Vec3 sensor_m;
  Vec3 velocity_m_s;
  Vec3 nadir;         // c1
  Vec3 side;          // c2
  Vec3 nadir_normal;  // the ellipsoid normal under the sensor (up)
  Geodetic sensor_geodetic;

  ZeroDopplerFrame(const OrbitState& s, LookSide look, const Ellipsoid& e);
  Vec3 point(double range_m, double look_rad) const {
    return sensor_m + (nadir * std::cos(look_rad) + side * std::sin(look_rad)) * range_m;
  }
  // The look angle at which a sphere of radius rho_m about the Earth's centre
  // is reached at slant range range_m (law of cosines), for initial guesses.
  double look_on_sphere(double range_m, double rho_m) const;
  // The slant range at which the ray at look angle look_rad meets the
  // ellipsoid inflated by height_m (axes a + h, b + h: within millimetres of
  // the surface at height h for the heights of terrain), the nearer root of
  // |D (p + t u)|^2 = 1, D = diag(1/(a+h), 1/(a+h), 1/(b+h)); NaN when the
  // ray misses it.
  double range_to_ellipsoid(double look_rad, const Ellipsoid& e, double height_m) const;
};

struct GroundPoint {
  Vec3 ecef_m;
  Geodetic geodetic;
  double look_rad = 0.0;
  int iterations = 0;
  bool converged = false;
};

// rdr2geo on a height model: height_fn(lat_rad, lon_rad) -> ellipsoidal
// height in metres (NaN: no data). Iterates until the point's ellipsoidal
// height matches the model's within tol_m. A template, so a DEM's bilinear
// lookup inlines into the loop (no virtual call per sample).
template <typename HeightFn>
GroundPoint rdr2geo(const ZeroDopplerFrame& f, const Ellipsoid& e, double range_m,
                    HeightFn&& height_fn, double h_guess_m,
                    double look_guess_rad = std::numeric_limits<double>::quiet_NaN(),
                    double tol_m = 1e-5, int max_iter = 40) {
  GroundPoint out;
  // Initial look angle: the caller's (a neighbouring pixel's), else the
  // sphere through the ellipsoid point under the sensor raised by the
  // guessed height.
  double th0 = look_guess_rad;
  if (!std::isfinite(th0)) {
    const Geodetic& sub = f.sensor_geodetic;
    const double rho = e.to_ecef({sub.lat_rad, sub.lon_rad, h_guess_m}).norm();
    th0 = f.look_on_sphere(range_m, rho);
  }
  // g(theta) = ellipsoidal height of X(theta) - model height there.
  const auto g = [&](double th, GroundPoint& gp) {
    gp.ecef_m = f.point(range_m, th);
    gp.geodetic = e.to_geodetic(gp.ecef_m);
    return gp.geodetic.height_m - height_fn(gp.geodetic.lat_rad, gp.geodetic.lon_rad);
  };
  GroundPoint a;
  double ga = g(th0, a);
  if (!std::isfinite(ga)) return out;
  // First step: Newton on the ellipsoid part, dh/dtheta = n . dX/dtheta.
  const double cs = std::cos(th0), sn = std::sin(th0);
  const Vec3 dx = (f.side * cs - f.nadir * sn) * range_m;
  const double slope = Ellipsoid::normal(a.geodetic.lat_rad, a.geodetic.lon_rad).dot(dx);
  double th1 = th0 - ga / slope;
  GroundPoint b;
  double gb = g(th1, b);
  int it = 1;
  while (std::isfinite(gb) && std::abs(gb) > tol_m && it < max_iter) {
    double th2 = th1 - gb * (th1 - th0) / (gb - ga);
    // Safeguard: a secant step may not move further than ten ellipsoid
    // Newton steps would (flat spots in the DEM).
    const double cap = 10.0 * std::abs(gb / slope);
    if (!std::isfinite(th2) || std::abs(th2 - th1) > cap) th2 = th1 - gb / slope;
    th0 = th1;
    ga = gb;
    th1 = th2;
    gb = g(th1, b);
    ++it;
  }
  out = b;
  out.look_rad = th1;
  out.iterations = it;
  out.converged = std::isfinite(gb) && std::abs(gb) <= tol_m;
  return out;
}

}  // namespace ris
