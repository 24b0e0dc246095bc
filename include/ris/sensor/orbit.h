// A platform's orbit (or flight path): ECEF state vectors (time, position,
// velocity) and their interpolation.
//
// Times are seconds since the orbit's reference epoch (a UTC date-time), as
// NISAR products and ISCE3's isce3::core::Orbit keep them, so doubles hold
// microseconds over days. Interpolation is the third-order (cubic) Hermite
// polynomial through the two state vectors around t, matching positions and
// velocities at both (ISCE3's OrbitInterpMethod::Hermite; NISAR products
// specify it): exact for motion of constant acceleration's derivative, error
// of order h^4 x''''/384, below a millimetre for 10-s Sentinel-1 vectors.
// Velocity and acceleration are the polynomial's derivatives, so the
// zero-Doppler Newton iteration (ris/geometry/zero_doppler.h) sees a
// consistent slope.
//
// Example:
//   ris::Orbit orbit(epoch, state_vectors);  // checked: >= 2, increasing times
//   ris::OrbitState s = orbit.interpolate(t_s);  // s.position_m, s.velocity_m_s
#pragma once

#include <string>
#include <vector>

#include "ris/util/utc_time.h"
#include "ris/util/vec3.h"

namespace ris {

struct StateVector {
  double time_s = 0.0;  // since the orbit's epoch
  Vec3 position_m;      // ECEF
  Vec3 velocity_m_s;    // ECEF
};

struct OrbitState {
  Vec3 position_m;
  Vec3 velocity_m_s;
  Vec3 acceleration_m_s2;
};

class Orbit {
 public:
  Orbit() = default;
  // Throws InputError (naming source) unless there are at least two state
  // vectors with strictly increasing times.
  Orbit(UtcTime epoch, std::vector<StateVector> state_vectors, const std::string& source = "");

  const UtcTime& epoch() const { return epoch_; }
  const std::vector<StateVector>& state_vectors() const { return sv_; }
  double start_s() const { return sv_.front().time_s; }
  double end_s() const { return sv_.back().time_s; }
  bool covers(double t_s) const { return t_s >= start_s() && t_s <= end_s(); }

  // Position, velocity and acceleration at t (clamped to the covered span:
  // callers check covers() where it matters). No allocation.
  OrbitState interpolate(double t_s) const;

 private:
  std::size_t interval_of(double t_s) const;

  UtcTime epoch_;
  std::vector<StateVector> sv_;
  bool uniform_ = false;  // equally spaced times: the interval by division
  double spacing_s_ = 0.0;
};

}  // namespace ris
