// The along-line scans of the geometry stage, shared by every mode whose
// geometry is a set of ground lines seen from one vertical plane: SLAR and SAR
// zero-Doppler lines (ris/geometry/slar_geometry.h) and PPI rays
// (ris/geometry/ppi_geometry.h). Along such a line the sensor sits at ground
// distance u = 0 and altitude H; samples are ordered by increasing u
// (MODEL.md section 2, "Cast shadow", "Layover", "PPI").
//
//   line_element_ends        slant range of each element's near and far ends
//   mark_shadow_and_layover  cast shadow (t = u / (H - h) not the largest so
//                            far) and the SNAP two-scan layover zone
//
// Example (one line of n samples, arrays of n values):
//   ris::LineSamples line{n, first_u_m, step_m, altitude_m, height, range, near_end,
//                         far_end, dh_du, flags};
//   ris::line_element_ends(line);
//   ris::mark_shadow_and_layover(line);
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "ris/geometry/terrain_sample.h"

namespace ris {

// Per-sample flags (bit values).
namespace sample_flag {
inline constexpr std::uint8_t kNoData = 1;      // the scene has no data here (NaN / no-data cell)
inline constexpr std::uint8_t kUnseen = 2;      // outside the scene, or not in front (u <= 0)
inline constexpr std::uint8_t kShadow = 4;      // cast shadow: max_{u'<u} t(u') > t(u)
inline constexpr std::uint8_t kBackFacing = 8;  // cos(local incidence) <= 0
inline constexpr std::uint8_t kLayover = 16;    // in the SNAP two-scan layover zone
}  // namespace sample_flag

// Whether a sample takes part in image formation (seen, has data, lit, facing).
inline bool sample_visible(std::uint8_t flags) {
  return (flags & (sample_flag::kNoData | sample_flag::kUnseen | sample_flag::kShadow |
                   sample_flag::kBackFacing)) == 0;
}

// A terrain sample seen from the sensor: ground distance u from the sensor's
// nadir along the unit ground look direction (look_x, look_y), sensor
// altitude H above the datum (> h).
struct SampleLook {
  double slant_range_m = 0.0;  // R = sqrt(u^2 + (H - h)^2)
  double incidence_rad = 0.0;  // atan2(u, H - h), the look angle from nadir
  double cos_local = 0.0;      // cos(theta_l) = n . l; <= 0: back-facing
  double dh_du = 0.0;          // slope along the look direction
  double normal_length = 1.0;  // |(-dz/dx, -dz/dy, 1)|: true area / horizontal area
};

inline SampleLook look_at(const TerrainSample& ts, double u_m, double altitude_m, double look_x,
                          double look_y) {
  SampleLook s;
  const double D = altitude_m - double(ts.height_m);
  s.slant_range_m = std::hypot(u_m, D);
  s.incidence_rad = std::atan2(u_m, D);
  // Slope along the look direction g and the facet normal's length
  // |(-dz/dx, -dz/dy, 1)| (MODEL.md section 2-3).
  s.dh_du = double(ts.dz_dx) * look_x + double(ts.dz_dy) * look_y;
  s.normal_length = std::sqrt(1.0 + double(ts.dz_dx) * ts.dz_dx + double(ts.dz_dy) * ts.dz_dy);
  // cos(theta_l) = n . l with l = (-u g + D z) / R: the slope across g
  // tilts n but is orthogonal to l, so only dh/du enters the numerator.
  s.cos_local = (u_m * s.dh_du + D) / (s.slant_range_m * s.normal_length);
  return s;
}

inline double local_incidence_rad(const SampleLook& s) {
  return std::acos(std::clamp(s.cos_local, -1.0, 1.0));
}

// One line's terrain, the input of look_line: per sample its ground distance
// u from the sensor's nadir, its height and its slope. Height and slope are
// NaN where the sample has no terrain (outside the scene, no data): its
// outputs are then NaN.
struct LineTerrain {
  int samples = 0;
  const float* u_m = nullptr;
  const float* height_m = nullptr;
  const float* dz_dx = nullptr;
  const float* dz_dy = nullptr;
};

// look_line's outputs, `samples` values each.
struct LineLook {
  float* slant_range_m = nullptr;
  float* incidence_rad = nullptr;  // may be null: not wanted (uniform elevation pattern)
  float* local_incidence_rad = nullptr;
  float* area_m2 = nullptr;
  float* dh_du = nullptr;
  std::uint8_t* flags = nullptr;  // kBackFacing is added where cos(theta_l) <= 0
};

// The sensor and element constants of look_line.
struct LineLookFrame {
  double altitude_m = 0.0;            // H
  double look_x = 0.0, look_y = 0.0;  // unit ground look direction
  double element_m2 = 0.0;            // horizontal area of one element
};

// look_at() and local_incidence_rad() over a whole line, in single precision
// and without branches so that it vectorises: R = sqrt(u^2 + D^2), the look
// angle atan(u / D) (D = H - h > 0), theta_l = atan2(|n x l|, n . l) (the
// same angle as look_at's acos(n . l), accurate near 0 in single precision),
// area = element_m2 |n|, atan by ris/util/fast_math.h. Differs from look_at
// only by float rounding (~1e-7; tested in line_scan_test.cpp).
void look_line(const LineTerrain& in, const LineLookFrame& frame, const LineLook& out);

// One line's samples: sample j at ground distance u_j = first_u_m + j step_m
// from the sensor's nadir. Pointers to `samples` values each; samples flagged
// kNoData or kUnseen are skipped by both scans.
struct LineSamples {
  int samples = 0;
  double first_u_m = 0.0;
  double step_m = 0.0;
  double altitude_m = 0.0;     // H, sensor above the datum
  const float* height_m;       // h
  const float* slant_range_m;  // R
  float* range_near_end_m;     // out: R at u - step/2
  float* range_far_end_m;      // out: R at u + step/2
  const float* dh_du;          // slope along the line (used where a neighbour lacks data)
  std::uint8_t* flags;         // in: kNoData / kUnseen (/ kBackFacing); out: + shadow, layover
};

// Which code line_element_ends and the scans run: the widest the CPU has
// (AVX-512 sixteen samples at a time, where it has it), or the portable one
// whatever the CPU (for tests: both give the same bytes).
enum class ScanKernel { best, portable };

// The element's ends: heights halfway to the neighbours with data (or the
// local slope's extrapolation where a neighbour has none), so a step in the
// terrain is shared by the two cells beside it.
void line_element_ends(const LineSamples& line, ScanKernel kernel = ScanKernel::best);

// Cast shadow and layover along the line (MODEL.md section 2). Samples not
// skipped (kNoData, kUnseen) must be in front of the sensor, u > 0.
void mark_shadow_and_layover(const LineSamples& line, ScanKernel kernel = ScanKernel::best);

}  // namespace ris
