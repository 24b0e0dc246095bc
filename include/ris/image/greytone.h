// Film greytones from mean (or speckled) power: the seed's equations 13 and
// 15 (MODEL.md section 3, "Greytone").
//
//   G = G_ref + (255/X) [ gamma log10(P / P_ref) + log10(k2/k1) + gamma log10(M2/M1) ]
//
// rounded to the nearest integer, then clamped to [0, 255] (0 black, 255
// white). A factor of 10 in power moves G by 255 gamma / X.
//
// What the switches do here and where: P arrives with the radar-equation
// factors that are switched off already replaced by their reference values
// (ris/image/greytone_terms.h explains the design); GreytoneMap adds the k and
// M terms only when switched on; fading enters as speckled power (P times the
// fading factor Y of ris/image/speckle.h), which is equation 21's
// G_fad = (255/X) gamma log10(Y) exactly, so the fading switch means "apply
// speckle or not".
//
// The reference:
//   explicit (reference.auto = false): P_ref from the reference cell
//     (reference_power_w()), G_ref = reference.greytone;
//   auto: P_ref = the median of the valid pixels' power, G_ref =
//     reference.auto_greytone. Valid: finite, > 0 (shadow is 0 and would drag
//     the median to -inf) and not masked. Take it from the mean power (before
//     speckle) so the grey scale does not depend on the fading seed.
//
// Example:
//   ris::GreytoneMap map = ris::make_greytone_map(radar, img.mean_power_w, no_data_mask);
//   std::vector<std::uint8_t> grey(img.mean_power_w.size());
//   ris::greytones(speckled_power, grey, map, no_data_mask);
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "ris/sensor/radar_params.h"

namespace ris {

class GreytoneMap {
 public:
  // p_ref_w: reference power P_ref (W, > 0); g_ref: its greytone.
  GreytoneMap(const RadarParams& radar, double p_ref_w, double g_ref);

  // Equation 15 as a real number, neither rounded nor clamped; -inf for P = 0.
  double greytone(double power_w) const { return offset_ + per_decade_ * std::log10(power_w); }
  // Rounded, then clamped to [0, 255]. NaN power gives 0.
  std::uint8_t quantised(double power_w) const {
    const double g = std::round(greytone(power_w));
    if (!(g > 0.0)) return 0;  // also NaN and -inf
    return g >= 255.0 ? std::uint8_t{255} : static_cast<std::uint8_t>(g);
  }

  // quantised() of a float power, without a logarithm: the greytone is the
  // number of thresholds at or below p, where threshold k is the smallest
  // float whose quantised() is k or more (found once, in the constructor, by
  // bisection over the floats with quantised() itself, so the two agree on
  // every float; tested). A table indexed by the float's top 16 bits (its
  // exponent and 7 mantissa bits: buckets 0.5% wide in power) gives the
  // greytone at the bucket's start; a fixed number of threshold compares
  // (max_steps_: the most thresholds any bucket holds, 1 for any ordinary
  // film) finishes it. No data-dependent branch: speckled power is random,
  // and a mispredicted "one more threshold?" cost more than the table.
  std::uint8_t quantised_fast(float power_w) const {
    if (!table_) return quantised(power_w);
    std::uint32_t bits = 0;
    std::memcpy(&bits, &power_w, sizeof bits);
    // Zero, negative and NaN powers read bucket 0, whose greytone is 0 and
    // whose thresholds they are all below (NaN compares false): greytone 0.
    const std::uint32_t b = power_w > 0.0f ? bits >> 16 : 0u;  // +inf: its own bucket
    unsigned g = bucket_[b];
    for (unsigned s = 0; s < max_steps_; ++s) g += power_w >= threshold_[g + 1] ? 1u : 0u;
    return static_cast<std::uint8_t>(g);
  }

  // greytone_line (below): quantised_fast over a row, with the mask.
  void quantise_line(const float* power_w, const std::uint8_t* mask, std::uint8_t mask_bits,
                     std::size_t n, std::uint8_t* out, std::uint8_t no_data_greytone) const;

  double reference_power_w() const { return p_ref_w_; }
  double reference_greytone() const { return g_ref_; }
  double greytones_per_decade() const { return per_decade_; }  // 255 gamma / X
  // (255/X) [log10(k2/k1) + gamma log10(M2/M1)] with the switches applied.
  double film_offset() const { return film_offset_; }

 private:
  double p_ref_w_;
  double g_ref_;
  double per_decade_;
  double film_offset_;
  double offset_;  // G_ref + film_offset - per_decade log10(P_ref)
  // threshold_[k]: the smallest float power with quantised() >= k (k >= 1;
  // +inf when none); threshold_[0] unused; threshold_[256] NaN, which no
  // power reaches (the compares past greytone 255 stay false).
  std::array<float, 257> threshold_{};
  unsigned max_steps_ = 0;  // the most thresholds inside one bucket
  bool table_ = false;      // false: greytones do not grow with power (never in practice)
  // bucket_[b]: the greytone of the smallest positive float whose top 16 bits
  // are b (b up to +inf's 0x7f80).
  std::vector<std::uint8_t> bucket_;
  // bucket_step_[b] (the AVX2 kernel's one gather when max_steps_ == 1):
  // bucket_[b] << 17 | the low 17 bits of (the bucket's threshold's bits -
  // (b << 16)), 0x10000 when no threshold lies in the bucket after its first
  // float. A power in bucket b then has greytone bucket_[b] + 1 exactly when
  // its bits reach (b << 16) + those 17 bits (positive floats order as
  // their bits).
  std::vector<std::uint32_t> bucket_step_;
};

// Median of the valid pixels of `power_w` (see above); NaN when none is valid.
// no_data: empty, or one byte per pixel, non-zero = no data.
double median_valid_power_w(std::span<const float> power_w,
                            std::span<const std::uint8_t> no_data = {});

// The same over the pixels whose mask has none of mask_bits set (an image's
// pixel_flag mask, read directly: no separate no-data array).
double median_valid_power_w(std::span<const float> power_w, std::span<const std::uint8_t> mask,
                            std::uint8_t mask_bits);

// The radar's greytone map for an image: explicit reference, or auto from the
// median of `mean_power_w`. Throws InputError (radar file, key "reference")
// when auto finds no valid pixel, and (key "reference.category") when the
// reference sigma0 is a category that was not resolved
// (resolve_reference_sigma0, ris/image/greytone_terms.h).
GreytoneMap make_greytone_map(const RadarParams& radar, std::span<const float> mean_power_w,
                              std::span<const std::uint8_t> no_data = {});
// The same when the median of the valid pixels is already known (a streamed
// image, ris/sim/slar_stream.h): median_power_w is used only by the auto
// reference (NaN: no valid pixel).
GreytoneMap make_greytone_map_for_median(const RadarParams& radar, double median_power_w);

// One row of greytones, the kernel of greytones() and of the fused render
// (ris/sim/slar_simulation.h): out[i] = no_data_greytone where power_w[i] is
// NaN or mask[i] & mask_bits is non-zero (mask may be null), else
// map.quantised_fast(power_w[i]) (the same bytes).
inline void greytone_line(const GreytoneMap& map, const float* power_w, const std::uint8_t* mask,
                          std::uint8_t mask_bits, std::size_t n, std::uint8_t* out,
                          std::uint8_t no_data_greytone = 0) {
  map.quantise_line(power_w, mask, mask_bits, n, out, no_data_greytone);
}

// Maps a power raster to greytones, in parallel (OpenMP over blocks of pixels;
// the result does not depend on the thread count). NaN pixels and masked
// pixels (no_data non-zero) get no_data_greytone. out.size() == power_w.size().
void greytones(std::span<const float> power_w, std::span<std::uint8_t> out, const GreytoneMap& map,
               std::span<const std::uint8_t> no_data = {}, std::uint8_t no_data_greytone = 0);

}  // namespace ris
