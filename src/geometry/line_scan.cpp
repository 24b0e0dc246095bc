#include "ris/geometry/line_scan.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace ris {

namespace {
constexpr std::uint8_t kSkip = sample_flag::kNoData | sample_flag::kUnseen;
}

void line_element_ends(const LineSamples& l) {
  const double H = l.altitude_m;
  const double half_step = 0.5 * l.step_m;
  const auto has_data = [&](int j) { return j >= 0 && j < l.samples && !(l.flags[j] & kSkip); };
  for (int j = 0; j < l.samples; ++j) {
    if (!has_data(j)) continue;
    const double h = l.height_m[j];
    const double slope_half = double(l.dh_du[j]) * half_step;
    const double h_near = has_data(j - 1) ? 0.5 * (h + l.height_m[j - 1]) : h - slope_half;
    const double h_far = has_data(j + 1) ? 0.5 * (h + l.height_m[j + 1]) : h + slope_half;
    const double u = l.first_u_m + j * l.step_m;
    l.range_near_end_m[j] = static_cast<float>(std::hypot(u - half_step, H - h_near));
    l.range_far_end_m[j] = static_cast<float>(std::hypot(u + half_step, H - h_far));
  }
}

void mark_shadow_and_layover(const LineSamples& l) {
  const double H = l.altitude_m;
  // Cast shadow: a point is shadowed when a nearer point has a larger look
  // angle from nadir psi = atan2(u, H - h) (MODEL.md section 2: t = tan psi =
  // u / (H - h) where H > h). Compared as psi_max > psi <=> D u_max - u D_max
  // > 0 with D = H - h (the sine of the angle difference), which also holds
  // for terrain above the antenna (a PPI on a mast among hills).
  double u_max = 0.0, d_max = 0.0;
  bool any = false;
  for (int j = 0; j < l.samples; ++j) {
    if (l.flags[j] & kSkip) continue;
    const double u = l.first_u_m + j * l.step_m;
    const double d = H - double(l.height_m[j]);
    if (!any || d * u_max - u * d_max < 0.0) {
      u_max = u;  // psi >= psi_max: the new horizon
      d_max = d;
      any = true;
    } else if (d * u_max - u * d_max > 0.0) {
      l.flags[j] |= sample_flag::kShadow;
    }
  }
  // Layover, SNAP definition: near to far keeping the largest R, a smaller R
  // is layover; far to near keeping the smallest R, a larger R is layover.
  float max_r = -std::numeric_limits<float>::infinity();
  for (int j = 0; j < l.samples; ++j) {
    if (l.flags[j] & kSkip) continue;
    if (l.slant_range_m[j] < max_r) l.flags[j] |= sample_flag::kLayover;
    max_r = std::max(max_r, l.slant_range_m[j]);
  }
  float min_r = std::numeric_limits<float>::infinity();
  for (int j = l.samples - 1; j >= 0; --j) {
    if (l.flags[j] & kSkip) continue;
    if (l.slant_range_m[j] > min_r) l.flags[j] |= sample_flag::kLayover;
    min_r = std::min(min_r, l.slant_range_m[j]);
  }
}

}  // namespace ris
