// Internal: image formation of one line, its elements into its range profile,
// shared by form_slar_image (the stage path) and the fused line pipelines
// (ris/sim/slar_line_blocks.h, slar_oblique_lines.cpp) so that all give the
// same bytes.
//
// Each visible element returns P_i (the radar equation, MODEL.md section 3,
// seed equations 1 and 3-5) spread over its slant-range span, half from its
// near end to its centre and half from its centre to its far end
// (ris/image/slar_image.h). form_line_profile does it in passes over the line
// rather than element by element: branch-free passes (vectorised) compute
// each element's first bin and the fraction of it in the next bin (almost
// every element lies within two bins; bin coordinates in single precision)
// and its power (element_power_ratio: single precision, then double), a
// scatter pass adds them into four interleaved copies of the profile (consecutive elements usually
// fall in the same bin; one copy would chain every add through memory), the rare element spanning
// more bins (or the swath's edge) goes through spread(), and a last pass sums the copies into the
// profile.
//
// Example (one line of n elements, a profile of `bins` bins):
//   const ris::detail::SlarElementContext ctx = ris::detail::element_context(p, gain2, lut, bins);
//   ris::detail::LineElementScratch scratch(n, bins);  // per thread, once
//   ris::detail::LineElementTally t = ris::detail::form_line_profile(
//       ctx, {n, flags, range, near_end, far_end, incidence, local_incidence, area, category},
//       scratch, {touch, mapped, visible, acc, acc_area}, nullptr);
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
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
// zero-length interval puts everything into its bin. Bin b is acc[b *
// stride] (and acc_area[b * stride]): stride 2 for interleaved pairs.
// spread_fractions calls add(b, f) with the fraction f of the interval in
// each bin b it touches (spread's arithmetic, for any accumulator).
template <class Add>
inline void spread_fractions(double x0, double x1, int bins, Add add) {
  const double lo = std::min(x0, x1), hi = std::max(x0, x1);
  if (hi < 0.0 || lo >= bins) return;
  const int b0 = first_bin(lo), b1 = last_bin(hi, bins);
  const double width = hi - lo;
  if (b0 == b1 && width <= 0.0) {
    add(b0, 1.0);  // x * 1.0 is x: the whole value, exactly
    return;
  }
  const double inv_width = 1.0 / width;
  for (int b = b0; b <= b1; ++b) {
    add(b, (std::min(hi, double(b + 1)) - std::max(lo, double(b))) * inv_width);
  }
}
inline void spread(double* acc, double* acc_area, double x0, double x1, double power, double area,
                   int bins, std::size_t stride = 1) {
  spread_fractions(x0, x1, bins, [&](int b, double f) {
    acc[static_cast<std::size_t>(b) * stride] += power * f;
    acc_area[static_cast<std::size_t>(b) * stride] += area * f;
  });
}

// The constant part of one run's image formation.
struct SlarElementContext {
  double near_m = 0.0, inv_dr = 0.0;
  int bins = 0;
  double k_radar = 0.0;  // P_t lambda^2 / (4 pi)^3
  const TwoWayGainTable* gain2 = nullptr;
  const Sigma0Lut* lut = nullptr;
  // The two tables as (value, next value - value) pairs, entry k at [2k]:
  // the power pass's lookups load one pair per element instead of two
  // values (sigma0: the same differences as Sigma0Lut::interpolate()
  // computes, so the same results). The gain in single precision, as the
  // per-element power (element_power_ratio).
  std::vector<float> gain2_pairs;
  std::vector<float> sigma0_pairs;
  float g2_uniform = 0.0f;   // the gain when the table is uniform
  double power_scale = 0.0;  // k_radar 2^-40: element_power_ratio's scale
};

SlarElementContext element_context(const SlarImagingParams& p, const TwoWayGainTable& gain2,
                                   const Sigma0Lut& lut, int bins);

// A visible element's received power P_i = k G^2 sigma0 A / R^4 with k = P_t
// lambda^2 / (4 pi)^3 (MODEL.md section 3, seed equations 1 and 3-5).
inline double radar_power_w(double k_radar, double gain2, float sigma0, float area_m2,
                            double slant_range_m) {
  const double r2 = slant_range_m * slant_range_m;
  return k_radar * gain2 * double(sigma0) * double(area_m2) / (r2 * r2);
}

// The per-element power's variable part in single precision: G^2 sigma0 A /
// (R 2^-10)^4, so that P_i = double(ratio) * k_radar 2^-40
// (SlarElementContext::power_scale; the radar equation as radar_power_w).
// Why float: eight elements per instruction and one single-precision
// division instead of two double ones; the inputs are floats already and
// the result's relative error (< 1e-6, five roundings) is far below
// anything the image resolves; accumulation stays in double. Why 2^-10
// (exact): R^4 in metres reaches 1e20 and small sigma0 x gain products
// would bring the ratio near float's smallest normal values; in units of
// 1024 m, R^4 stays within ~1e-12 (R = 1 m) to 1e16 (R = 10^7 m) and the
// ratio well inside float's range. The order of the operations is part of
// the definition (vectorised and scalar lanes give the same bits).
// F: float, or a GCC vector of floats (the power pass's eight lanes, in
// kernels/image/slar_element.cpp; -Wpsabi, GCC's note on vectors passed by
// value, is off for src/kernels/ only and moot for an inlined function).
template <typename F>
__attribute__((always_inline)) inline F element_power_ratio(F gain2, F sigma0, F area_m2,
                                                            F slant_range_m) {
  const F r = slant_range_m * 0x1p-10f;
  const F r2 = r * r;
  return gain2 * sigma0 * area_m2 / (r2 * r2);
}
inline constexpr double kElementPowerScale = 0x1p-40;

// One line's elements, `samples` values each (the geometry's per-sample
// arrays at the line's start, or a fused pipeline's line scratch).
struct LineElements {
  int samples = 0;
  const std::uint8_t* flags = nullptr;  // sample_flag bits
  const float* slant_range_m = nullptr;
  const float* near_end_m = nullptr;     // slant range of the element's near end
  const float* far_end_m = nullptr;      // and far end
  const float* incidence_rad = nullptr;  // look angle from nadir; unread when the gain is uniform
  const float* local_incidence_rad = nullptr;
  const float* area_m2 = nullptr;
  const std::uint16_t* category = nullptr;
  // Element 0's index on its whole line, when these elements are a span of
  // it (the oblique fused path clips lines to the scene): the profile copy
  // an element adds to follows its index on the line, so that a span and
  // the whole line sum in the same groups and give the same bytes.
  int first_index = 0;
};

// The line's outputs: its rows of SlarLineProfiles (touch bits and centre
// counts, added to) and its profile before the range window (`bins` values
// each, overwritten).
struct LineProfileRow {
  std::uint8_t* touch = nullptr;
  std::uint16_t* mapped_count = nullptr;
  std::uint16_t* visible_count = nullptr;
  double* power_w = nullptr;
  double* area_m2 = nullptr;
};

// What form_line_profile saw on the line.
struct LineElementTally {
  std::int64_t in_swath = 0;  // elements with data whose centre falls in a bin
  std::int64_t nodata = 0, shadow = 0, back_facing = 0, layover = 0;  // elements with the flag
  std::int64_t general = 0;  // elements left to spread() (more than two bins, the swath's edge)
  float r_min_m = std::numeric_limits<float>::infinity();  // slant range of the elements with data
  float r_max_m = -std::numeric_limits<float>::infinity();
};

// One thread's scratch for form_line_profile, allocated once.
struct LineElementScratch {
  // Interleaved profile copies: the element at index j on its line adds to
  // copy j % 4.
  static constexpr int kCopies = 4;
  int bins = 0;
  // Per element: the first bin touched (`bins`, a spare, for an element the
  // scatter pass skips), the fraction of the power in the next bin, the
  // touch bits, counts and where the centre is (form_line_profile's kCode*),
  // element_power_ratio and the area (0 where not visible); the elements
  // left to spread().
  std::vector<std::int32_t> first, code;
  std::vector<float> frac_next, ratio, area;
  std::vector<std::int32_t> general;  // the first n_general are used
  int n_general = 0;
  // Per copy and bin (+ 2 spares): the (power, area) sums interleaved (2
  // values a bin: one 16-byte add per bin an element touches), the centre
  // counts packed (all centres in the low 32 bits, visible ones in the high
  // 32: one add), the touch bits.
  std::vector<double> acc;
  std::vector<std::uint64_t> counts;
  std::vector<std::uint8_t> touch;
  // The line form_line_profile formed last: its elements, range bins and
  // the bins it added to, [lo, hi) (the further channels' inputs).
  struct Formed {
    int samples = -1;
    double near_m = 0.0, inv_dr = 0.0;
    int lo = 0, hi = 0;
  } formed;
  // Passes 1-2 work a chunk of elements at a time (the L1 cache).
  static constexpr int kChunk = 256;
  // The further channels (the channel axis; reserve_channels): their
  // number; per channel its four power-only profile copies (channel k copy q
  // bin b at (k kCopies + q) stride + b), a chunk of power ratios, the
  // ratios of pass 3's elements; the first channel's area profile (every
  // channel's: it follows from the geometry).
  int channels = 0;
  std::vector<double> channel_acc;
  std::vector<float> channel_ratio, channel_general_ratio;
  std::vector<double> formed_area;
  void reserve_channels(int n);
  LineElementScratch(int samples, int bins);
  std::size_t stride() const { return static_cast<std::size_t>(bins) + 2; }
};

// Image formation's per-line step: the line's elements (those flagged
// kNoData or kUnseen are skipped) into `out`. element_power_w, when not
// null, receives P_i of each visible element (0 for the others), `samples`
// values (the coherent SAR's input). The elevation gain is read at the look
// angle from nadir unless the table is uniform.
LineElementTally form_line_profile(const SlarElementContext& c, const LineElements& e,
                                   LineElementScratch& s, const LineProfileRow& out,
                                   float* element_power_w);

// The further channels of the line form_line_profile has just formed in s,
// from the same elements e (the channel axis: other frequencies,
// polarisations or backscatter sources over one geometry;
// s.reserve_channels(channels.size()) first). Only an element's power
// depends on the channel (its radar equation, gain and sigma0), so only
// that is computed again; the bins, fractions and pass-3 list are the first
// channel's, read from s, and each element's bin is read once for all the
// channels. Their profiles stay in s until merge_channel; each is the
// same bytes as form_line_profile with its context would give, and so is
// the area (s.formed_area, the first channel's). The contexts' range bins
// must be the first channel's (checked).
// element_power_w (empty, or one pointer per channel, each null or `samples`
// values): P_i of each element for that channel, as form_line_profile's
// element_power_w gives the first channel's (a quad-pol SAR's input).
void scatter_channel_elements(std::span<const SlarElementContext* const> channels,
                              const LineElements& e, LineElementScratch& s,
                              std::span<float* const> element_power_w = {});

// Channel `channel`'s profile (power, before the range window: `bins`
// values, overwritten) from its copies, which are cleared for the next line.
void merge_channel(LineElementScratch& s, int channel, double* power_w);

}  // namespace ris::detail
