#include "ris/sensor/orbit.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ris/util/error.h"

namespace ris {

Orbit::Orbit(UtcTime epoch, std::vector<StateVector> state_vectors, const std::string& source)
    : epoch_(epoch), sv_(std::move(state_vectors)) {
  if (sv_.size() < 2) {
    throw InputError(source, "orbit",
                     fmt::format("expected at least 2 state vectors, got {}", sv_.size()));
  }
  for (std::size_t i = 1; i < sv_.size(); ++i) {
    if (!(sv_[i].time_s > sv_[i - 1].time_s)) {
      throw InputError(source, "orbit",
                       fmt::format("state vector times must increase: vector {} at {} s follows "
                                   "{} s",
                                   i, sv_[i].time_s, sv_[i - 1].time_s));
    }
  }
  spacing_s_ = (end_s() - start_s()) / static_cast<double>(sv_.size() - 1);
  uniform_ = true;
  for (std::size_t i = 1; i < sv_.size(); ++i) {
    const double d = sv_[i].time_s - sv_[i - 1].time_s;
    if (std::abs(d - spacing_s_) > 1e-6 * spacing_s_) uniform_ = false;
  }
}

std::size_t Orbit::interval_of(double t_s) const {
  const std::size_t last = sv_.size() - 2;
  if (uniform_) {
    const double k = std::floor((t_s - start_s()) / spacing_s_);
    if (k <= 0.0) return 0;
    return std::min(static_cast<std::size_t>(k), last);
  }
  const auto it = std::upper_bound(sv_.begin(), sv_.end(), t_s,
                                   [](double t, const StateVector& s) { return t < s.time_s; });
  const auto idx = static_cast<std::size_t>(std::max<std::ptrdiff_t>(it - sv_.begin() - 1, 0));
  return std::min(idx, last);
}

// Cubic Hermite on [t0, t1] with s = (t - t0)/h:
//   p(s) = h00 p0 + h10 h v0 + h01 p1 + h11 h v1,
//   h00 = 2s^3 - 3s^2 + 1, h10 = s^3 - 2s^2 + s, h01 = -2s^3 + 3s^2, h11 = s^3 - s^2
// and its first and second derivatives (divided by h and h^2).
OrbitState Orbit::interpolate(double t_s) const {
  t_s = std::clamp(t_s, start_s(), end_s());
  const std::size_t i = interval_of(t_s);
  const StateVector& a = sv_[i];
  const StateVector& b = sv_[i + 1];
  const double h = b.time_s - a.time_s;
  const double s = (t_s - a.time_s) / h;
  const double s2 = s * s, s3 = s2 * s;
  const double h00 = 2 * s3 - 3 * s2 + 1, h10 = s3 - 2 * s2 + s, h01 = -2 * s3 + 3 * s2,
               h11 = s3 - s2;
  const double d00 = 6 * s2 - 6 * s, d10 = 3 * s2 - 4 * s + 1, d01 = -6 * s2 + 6 * s,
               d11 = 3 * s2 - 2 * s;
  const double e00 = 12 * s - 6, e10 = 6 * s - 4, e01 = -12 * s + 6, e11 = 6 * s - 2;
  OrbitState o;
  o.position_m = a.position_m * h00 + a.velocity_m_s * (h10 * h) + b.position_m * h01 +
                 b.velocity_m_s * (h11 * h);
  o.velocity_m_s = (a.position_m * d00 + b.position_m * d01) * (1.0 / h) + a.velocity_m_s * d10 +
                   b.velocity_m_s * d11;
  o.acceleration_m_s2 = (a.position_m * e00 + b.position_m * e01) * (1.0 / (h * h)) +
                        (a.velocity_m_s * e10 + b.velocity_m_s * e11) * (1.0 / h);
  return o;
}

}  // namespace ris
