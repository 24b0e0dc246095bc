// Orbits ris makes itself when there is no product to read: a circular
// Keplerian orbit (a planned spaceborne radar) and a flight line at constant
// height (an airborne radar), sampled into state vectors so that every
// geometry routine treats them like a real product's orbit.
#pragma once

#include "ris/sensor/orbit.h"
#include "ris/util/ellipsoid.h"

namespace ris {

// A circular orbit in an inertial frame that coincides with ECEF at t = 0;
// the Earth turns under it at kEarthRotation_rad_s. At t = 0 the satellite
// is at argument of latitude u0 on an orbit whose ascending node is at
// longitude lon_node. Radius = the ellipsoid's semi-major axis + altitude;
// angular rate sqrt(GM / r^3) (GM of WGS 84).
struct CircularOrbitParams {
  double altitude_m = 700e3;
  double inclination_rad = 0.0;
  double ascending_node_lon_rad = 0.0;
  double argument_of_latitude_rad = 0.0;
};

// A flight at constant height above the ellipsoid along a great circle of
// the sphere of the start point's mean radius sqrt(M N), at constant speed
// (the platform's speed at its height).
struct FlightLineParams {
  double lat_rad = 0.0, lon_rad = 0.0;  // position at t = 0
  double height_m = 0.0;
  double heading_rad = 0.0;  // clockwise from north
  double speed_m_s = 0.0;
};

constexpr double kEarthRotation_rad_s = 7.292115e-5;  // WGS 84 (NIMA TR8350.2)
constexpr double kEarthGm_m3_s2 = 3.986004418e14;     // WGS 84 (NIMA TR8350.2)

// State vectors every step_s from t0_s to t1_s (inclusive, rounded outwards).
Orbit make_circular_orbit(const CircularOrbitParams& p, const Ellipsoid& e, UtcTime epoch,
                          double t0_s, double t1_s, double step_s);
Orbit make_flight_line_orbit(const FlightLineParams& p, const Ellipsoid& e, UtcTime epoch,
                             double t0_s, double t1_s, double step_s);

}  // namespace ris
