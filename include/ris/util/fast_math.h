// Branch-free single-precision arc cosine and arc tangent for the per-sample
// hot loops (geometry over a line), so that a loop over a line vectorises:
// libm's acos/atan2 are scalar calls of ~40 cycles each, and the results are
// stored as float anyway.
//
// Both are the Cephes Math Library's single-precision algorithms (S. L.
// Moshier, Cephes 2.2, asinf.c and atanf.c: range reduction plus a degree-4
// minimax polynomial in x^2; peak relative error ~2.5e-7 and ~1.9e-7 over
// the full range), written with selects instead of branches. Tested against
// libm over [-1, 1] and [-1e4, 1e4] in fast_math_test.cpp (a few float ulps).
// NaN in gives NaN out.
//
// Example:
//   float theta_l = ris::fast_acos(cos_local);   // cos_local in [-1, 1]
//   float look = ris::fast_atan(u_m / d_m);      // = atan2(u, d) for d > 0
#pragma once

#include <cmath>

namespace ris {

inline constexpr float kPiF = 3.14159265358979323846f;

// asin(s) for 0 <= s <= 0.5 (Cephes asinf's polynomial), z = s^2.
inline float asin_poly(float s, float z) {
  const float p =
      (((4.2163199048e-2f * z + 2.4181311049e-2f) * z + 4.5470025998e-2f) * z + 7.4953002686e-2f) *
          z +
      1.6666752422e-1f;
  return p * z * s + s;
}

// acos(x) for x in [-1, 1] (clamp first: outside it gives a finite wrong
// value, not NaN). acos(a) = pi/2 - asin(a) for a <= 1/2, and
// 2 asin(sqrt((1 - a)/2)) above, where the first would lose precision.
inline float fast_acos(float x) {
  const float a = std::fabs(x);
  const bool big = a > 0.5f;
  const float z = big ? 0.5f * (1.0f - a) : a * a;
  const float s = big ? std::sqrt(z) : a;
  const float p = asin_poly(s, z);
  const float r = big ? 2.0f * p : 0.5f * kPiF - p;
  return x < 0.0f ? kPiF - r : r;
}

// atan(x) for any x (Cephes atanf): reduced to |t| <= tan(pi/8) by
// atan(a) = pi/2 + atan(-1/a) (a > tan(3pi/8)) or pi/4 + atan((a-1)/(a+1))
// (a > tan(pi/8)), one division in all.
inline float fast_atan(float x) {
  const float a = std::fabs(x);
  const bool g1 = a > 2.414213562373095f;
  const bool g2 = a > 0.4142135623730950f;
  const float num = g1 ? -1.0f : (g2 ? a - 1.0f : a);
  const float den = g1 ? a : (g2 ? a + 1.0f : 1.0f);
  const float t = num / den;
  const float y0 = g1 ? 0.5f * kPiF : (g2 ? 0.25f * kPiF : 0.0f);
  const float z = t * t;
  const float r = y0 + ((((8.05374449538e-2f * z - 1.38776856032e-1f) * z + 1.99777106478e-1f) * z -
                         3.33329491539e-1f) *
                            z * t +
                        t);
  return std::copysign(r, x);
}

}  // namespace ris
