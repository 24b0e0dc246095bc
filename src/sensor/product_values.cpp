#include "ris/sensor/product_values.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "ris/util/error.h"

namespace ris {
namespace {

std::string expected(const ValueRange& r) {
  return fmt::format("expected {} in [{:g}, {:g}]{}{}", r.what, r.lo, r.hi, *r.unit ? " " : "",
                     r.unit);
}

bool inside(double v, const ValueRange& r) {
  return std::isfinite(v) && v >= r.lo && v <= r.hi;
}

// A vector's size against r, naming the vector and its component values.
void require_norm(const Vec3& v, const ValueRange& r, const std::string& file,
                  const std::string& key, std::size_t index) {
  const double n = v.norm();
  if (inside(n, r)) return;
  throw InputError(file, key,
                   fmt::format("state vector {}: ({:g}, {:g}, {:g}) has length {:g}; {}", index,
                               v.x, v.y, v.z, n, expected(r)));
}

}  // namespace

double require_in_range(double value, const ValueRange& r, const std::string& file,
                        const std::string& key) {
  if (!inside(value, r))
    throw InputError(file, key, fmt::format("{}, got {:g}", expected(r), value));
  return value;
}

int require_whole_number(double value, std::int64_t lo, std::int64_t hi, const std::string& file,
                         const std::string& key) {
  RIS_CHECK(lo <= hi && lo >= std::numeric_limits<int>::min() &&
            hi <= std::numeric_limits<int>::max());
  // Compared as doubles first: casting a double outside int's range is
  // undefined behaviour.
  if (!std::isfinite(value) || value < static_cast<double>(lo) || value > static_cast<double>(hi) ||
      value != std::floor(value)) {
    throw InputError(file, key,
                     fmt::format("expected a whole number from {} to {}, got {:g}", lo, hi, value));
  }
  return static_cast<int>(value);
}

void require_increasing_in_range(const std::vector<double>& v, const ValueRange& r,
                                 const std::string& file, const std::string& key) {
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!inside(v[i], r)) {
      throw InputError(file, key,
                       fmt::format("element {} is {:g}; {} (every element)", i, v[i], expected(r)));
    }
    if (i > 0 && !(v[i] > v[i - 1])) {
      throw InputError(file, key,
                       fmt::format("element {} ({:g}) does not follow element {} ({:g}): expected "
                                   "strictly increasing values",
                                   i, v[i], i - 1, v[i - 1]));
    }
  }
}

void require_physical_state_vectors(const std::vector<StateVector>& sv, const std::string& file,
                                    const StateVectorKeys& keys) {
  for (std::size_t i = 0; i < sv.size(); ++i) {
    if (!inside(sv[i].time_s, kProductTimeRange)) {
      throw InputError(file, keys.time,
                       fmt::format("state vector {}: time {:g}; {}", i, sv[i].time_s,
                                   expected(kProductTimeRange)));
    }
    require_norm(sv[i].position_m, kOrbitRadiusRange, file, keys.position, i);
    require_norm(sv[i].velocity_m_s, kPlatformSpeedRange, file, keys.velocity, i);
  }
}

}  // namespace ris
