// Internal: one geometry element's contribution to its line's range profile,
// shared by form_slar_image and the fused line-block pipeline
// (ris/sim/slar_line_blocks.h) so both give the same bytes.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/image/slar_image.h"

namespace ris::detail {

// max(0, floor(lo)) and min(bins - 1, floor(hi)) for lo < bins and hi >= 0
// (the callers return before otherwise), by truncation: the same integers
// without std::floor, which is a ~20-instruction sequence without SSE4.1.
inline int first_bin(double lo) {
  return lo > 0.0 ? static_cast<int>(lo) : 0;
}
inline int last_bin(double hi, int bins) {
  return hi < bins ? static_cast<int>(hi) : bins - 1;
}

// Adds `power` spread uniformly over the bin-coordinate interval between x0
// and x1 (either order) to acc; the part outside [0, bins) is lost. A
// zero-length interval puts everything into its bin.
inline void spread(double* acc, double* acc_area, double x0, double x1, double power, double area,
                   int bins) {
  const double lo = std::min(x0, x1), hi = std::max(x0, x1);
  if (hi < 0.0 || lo >= bins) return;
  const int b0 = first_bin(lo), b1 = last_bin(hi, bins);
  const double width = hi - lo;
  if (b0 == b1 && width <= 0.0) {
    acc[b0] += power;
    acc_area[b0] += area;
    return;
  }
  const double inv_width = 1.0 / width;
  for (int b = b0; b <= b1; ++b) {
    const double f = (std::min(hi, double(b + 1)) - std::max(lo, double(b))) * inv_width;
    acc[b] += power * f;
    acc_area[b] += area * f;
  }
}

inline std::uint16_t saturating_increment(std::uint16_t v) {
  return v == std::numeric_limits<std::uint16_t>::max() ? v : static_cast<std::uint16_t>(v + 1);
}

// The constant part of one run's image formation.
struct SlarElementContext {
  double near_m = 0.0, inv_dr = 0.0;
  int bins = 0;
  double k_radar = 0.0;  // P_t lambda^2 / (4 pi)^3
  const TwoWayGainTable* gain2 = nullptr;
  const Sigma0Lut* lut = nullptr;
};

// A visible element's received power P_i: the radar equation (MODEL.md
// section 3, seed equations 1 and 3-5).
inline double element_power_w(const SlarElementContext& c, double slant_range_m,
                              float incidence_rad, float local_incidence_rad, float area_m2,
                              std::uint16_t category) {
  const double r2 = slant_range_m * slant_range_m;
  const double g2 = c.gain2->uniform() ? c.gain2->at(0.0) : c.gain2->at(incidence_rad);
  return c.k_radar * g2 * double(c.lut->at(category, local_incidence_rad)) * double(area_m2) /
         (r2 * r2);
}

// One element with data (flags without kNoData/kUnseen) of the line whose
// profile row starts at `row` (pointers into SlarLineProfiles at that row).
// Returns whether its centre falls in a bin (counts towards samples_in_swath).
inline bool accumulate_element(const SlarElementContext& c, std::uint8_t f, float slant_range_m,
                               float range_near_end_m, float range_far_end_m, float incidence_rad,
                               float local_incidence_rad, float area_m2, std::uint16_t category,
                               std::uint8_t* touch_row, std::uint16_t* mapped_row,
                               std::uint16_t* visible_row, double* acc, double* acc_area) {
  const double R = slant_range_m;
  const bool visible = sample_visible(f);
  const int bins = c.bins;
  bool in_swath = false;
  // Centre counts (the seed's shadow map).
  const double pos = (R - c.near_m) * c.inv_dr;
  if (pos >= 0.0 && pos < bins) {
    const std::size_t k = static_cast<std::size_t>(pos);
    mapped_row[k] = saturating_increment(mapped_row[k]);
    if (visible) visible_row[k] = saturating_increment(visible_row[k]);
    in_swath = true;
  }
  // The element's slant-range span and the bins it touches.
  const double r_a = range_near_end_m, r_b = range_far_end_m;
  const double lo = (std::min({r_a, r_b, R}) - c.near_m) * c.inv_dr;
  const double hi = (std::max({r_a, r_b, R}) - c.near_m) * c.inv_dr;
  if (hi < 0.0 || lo >= bins) return in_swath;
  const int b0 = first_bin(lo), b1 = last_bin(hi, bins);
  std::uint8_t bits = slar_touch::kData;
  if (visible) bits |= slar_touch::kVisible;
  if (visible && (f & sample_flag::kLayover)) bits |= slar_touch::kLayover;
  if (b0 == b1 && lo >= 0.0 && hi < bins) {
    // The whole element in one bin (most elements: a cell's slant span is
    // well under a bin): all its power and area go there, as the two halves'
    // spread() below would put them, without their divisions and loops.
    touch_row[b0] |= bits;
    if (!visible) return in_swath;
    acc[b0] += element_power_w(c, R, incidence_rad, local_incidence_rad, area_m2, category);
    acc_area[b0] += double(area_m2);
    return in_swath;
  }
  for (int b = b0; b <= b1; ++b) touch_row[b] |= bits;
  if (!visible) return in_swath;
  const double power = element_power_w(c, R, incidence_rad, local_incidence_rad, area_m2, category);
  // Half the element (near end to centre, centre to far end) each.
  const double half_area = 0.5 * double(area_m2);
  spread(acc, acc_area, (r_a - c.near_m) * c.inv_dr, pos, 0.5 * power, half_area, bins);
  spread(acc, acc_area, pos, (r_b - c.near_m) * c.inv_dr, 0.5 * power, half_area, bins);
  return in_swath;
}

}  // namespace ris::detail
