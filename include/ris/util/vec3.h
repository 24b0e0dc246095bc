// A three-vector of doubles for Earth-centred geometry (ECEF positions in
// metres, velocities in metres per second, unit vectors). Plain value type:
// no allocation, inlined arithmetic, usable in the per-cell loops.
//
// Example:
//   ris::Vec3 los = (sensor_m - target_m).normalized();
//   double cos_inc = los.dot(normal);
#pragma once

#include <cmath>

namespace ris {

struct Vec3 {
  double x = 0.0, y = 0.0, z = 0.0;

  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator*(double s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  constexpr double dot(const Vec3& o) const { return x * o.x + y * o.y + z * o.z; }
  constexpr Vec3 cross(const Vec3& o) const {
    return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x};
  }
  double norm() const { return std::sqrt(dot(*this)); }
  Vec3 normalized() const { return *this * (1.0 / norm()); }
};

constexpr Vec3 operator*(double s, const Vec3& v) {
  return v * s;
}

}  // namespace ris
