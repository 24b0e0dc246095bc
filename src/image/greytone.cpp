#include "ris/image/greytone.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

#include "ris/image/greytone_terms.h"
#include "ris/util/error.h"
#include "ris/util/float_select.h"

namespace ris {

GreytoneMap::GreytoneMap(const RadarParams& radar, double p_ref_w, double g_ref)
    : p_ref_w_(p_ref_w), g_ref_(g_ref) {
  RIS_CHECK(p_ref_w > 0.0 && std::isfinite(p_ref_w));
  const FilmParams& f = radar.film;
  const double scale = 255.0 / f.density_range;  // equation 13: G = (255 / X) D
  per_decade_ = scale * f.gamma;
  film_offset_ = 0.0;
  if (radar.switches.film_k) film_offset_ += scale * std::log10(f.k2 / f.k1);
  if (radar.switches.receiver_m) film_offset_ += scale * f.gamma * std::log10(f.m2 / f.m1);
  offset_ = g_ref_ + film_offset_ - per_decade_ * std::log10(p_ref_w_);
  // quantised() is non-decreasing in the power (log10 and rounding are), so
  // each threshold is found by bisection over the positive floats, whose bit
  // patterns order as they do.
  const auto as_float = [](std::uint32_t bits) {
    float out = 0.0f;
    std::memcpy(&out, &bits, sizeof out);
    return out;
  };
  constexpr std::uint32_t kInfBits = 0x7f800000u;
  table_ = per_decade_ > 0.0;
  if (!table_) return;
  threshold_[0] = 0.0f;
  for (unsigned k = 1; k < 256; ++k) {
    std::uint32_t lo = 0, hi = kInfBits;  // quantised(lo) < k; hi: answer candidate
    if (quantised(double(as_float(hi))) < k) {
      threshold_[k] = std::numeric_limits<float>::infinity();
      continue;
    }
    while (hi - lo > 1) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      if (quantised(double(as_float(mid))) >= k)
        hi = mid;
      else
        lo = mid;
    }
    threshold_[k] = as_float(hi);
  }
  threshold_[256] = std::numeric_limits<float>::quiet_NaN();
  // The number of thresholds at or below p (a binary search of 8 steps).
  const auto count_at_or_below = [&](float p) {
    unsigned k = 0;
    for (unsigned step = 128; step > 0; step >>= 1) k = p >= threshold_[k + step] ? k + step : k;
    return k;
  };
  // Each bucket's first float's greytone, and the most thresholds any bucket
  // holds after its first float (up to its last float, bits b << 16 | 0xffff).
  bucket_.assign((kInfBits >> 16) + 1, 0);
  max_steps_ = 0;
  for (std::uint32_t b = 0; b < bucket_.size(); ++b) {
    const unsigned k = count_at_or_below(as_float(b << 16));
    bucket_[b] = static_cast<std::uint8_t>(k);
    if (b < (kInfBits >> 16)) {
      max_steps_ = std::max(max_steps_, count_at_or_below(as_float((b << 16) | 0xffffu)) - k);
    }
  }
}

namespace {

// An AVX2 clone beside the SSE2 default (GCC function multiversioning, as
// ris/geometry/line_scan.cpp): the table lookups as gathers. Integer and
// compare operations only, so both clones give the same bytes.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RIS_GREYTONE_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define RIS_GREYTONE_CLONES
#endif

// quantise_line's loop for a fixed number of threshold steps (1 for any
// ordinary film: the compiler unrolls it).
template <unsigned Steps>
void quantise_kernel(const float* __restrict power_w, const std::uint8_t* __restrict mask,
                     std::uint8_t mask_bits, std::size_t n, std::uint8_t* __restrict out,
                     std::uint8_t no_data_greytone, const std::uint8_t* __restrict bucket,
                     const float* __restrict threshold, unsigned steps) {
  for (std::size_t i = 0; i < n; ++i) {
    const float p = power_w[i];
    std::uint32_t bits = 0;
    std::memcpy(&bits, &p, sizeof bits);
    // Negative powers and -0 read bucket 0 (greytone 0, below every
    // threshold), NaN and +inf the last bucket (NaN is masked below).
    const std::uint32_t b = std::min(bits >> 16, 0x7f80u) & ~(0u - (bits >> 31));
    unsigned g = bucket[b];
    for (unsigned s = 0; s < (Steps > 0 ? Steps : steps); ++s) g += p >= threshold[g + 1] ? 1u : 0u;
    const bool masked = std::isnan(p) || (mask != nullptr && (mask[i] & mask_bits) != 0);
    out[i] = masked ? no_data_greytone : static_cast<std::uint8_t>(g);
  }
}

RIS_GREYTONE_CLONES void quantise_one_step(
    const float* __restrict power_w, const std::uint8_t* __restrict mask, std::uint8_t mask_bits,
    std::size_t n, std::uint8_t* __restrict out, std::uint8_t no_data_greytone,
    const std::uint8_t* __restrict bucket, const float* __restrict threshold) {
  quantise_kernel<1>(power_w, mask, mask_bits, n, out, no_data_greytone, bucket, threshold, 1);
}

// The median of the powers keep(i) accepts besides being finite and > 0 (a
// parallel radix select, ris/util/float_select.h, not a sorted copy); the
// mean of the two middle values for an even count.
template <typename Keep>
double median_positive_power(std::span<const float> power_w, Keep keep) {
  const auto valid = [&](std::size_t i) {
    const float p = power_w[i];
    return std::isfinite(p) && p > 0.0f && keep(i);
  };
  const auto m = median_pair_float(power_w, valid);
  if (!m) return std::numeric_limits<double>::quiet_NaN();
  const double lower = m->first, upper = m->second;  // equal for an odd count
  if (lower == upper) return upper;
  return 0.5 * (lower + upper);
}

}  // namespace

void GreytoneMap::quantise_line(const float* power_w, const std::uint8_t* mask,
                                std::uint8_t mask_bits, std::size_t n, std::uint8_t* out,
                                std::uint8_t no_data_greytone) const {
  if (!table_) {
    for (std::size_t i = 0; i < n; ++i) {
      const float p = power_w[i];
      const bool masked = std::isnan(p) || (mask != nullptr && (mask[i] & mask_bits) != 0);
      out[i] = masked ? no_data_greytone : quantised(p);
    }
  } else if (max_steps_ == 1) {
    quantise_one_step(power_w, mask, mask_bits, n, out, no_data_greytone, bucket_.data(),
                      threshold_.data());
  } else {
    quantise_kernel<0>(power_w, mask, mask_bits, n, out, no_data_greytone, bucket_.data(),
                       threshold_.data(), max_steps_);
  }
}

double median_valid_power_w(std::span<const float> power_w, std::span<const std::uint8_t> no_data) {
  RIS_CHECK(no_data.empty() || no_data.size() == power_w.size());
  return median_positive_power(power_w,
                               [&](std::size_t i) { return no_data.empty() || no_data[i] == 0; });
}

double median_valid_power_w(std::span<const float> power_w, std::span<const std::uint8_t> mask,
                            std::uint8_t mask_bits) {
  RIS_CHECK(mask.size() == power_w.size());
  return median_positive_power(power_w, [&](std::size_t i) { return (mask[i] & mask_bits) == 0; });
}

GreytoneMap make_greytone_map(const RadarParams& radar, std::span<const float> mean_power_w,
                              std::span<const std::uint8_t> no_data) {
  return make_greytone_map_for_median(radar, radar.reference.automatic
                                                 ? median_valid_power_w(mean_power_w, no_data)
                                                 : std::numeric_limits<double>::quiet_NaN());
}

GreytoneMap make_greytone_map_for_median(const RadarParams& radar, double median) {
  const ReferenceCell& ref = radar.reference;
  if (ref.automatic) {
    if (!(median > 0.0)) {
      throw InputError(radar.source_file, "reference",
                       "auto reference: no pixel has a positive mean power (the swath saw "
                       "nothing); give an explicit reference or check the track");
    }
    return GreytoneMap(radar, median, ref.auto_greytone);
  }
  // A reference sigma0 given as a category is NaN until resolve_reference_sigma0().
  RIS_CHECK(ref.mean_power_w || !std::isnan(ref.sigma0));
  const double p_ref = reference_power_w(ref);
  if (!(p_ref > 0.0) || !std::isfinite(p_ref)) {
    throw InputError(radar.source_file, "reference",
                     fmt::format("the reference cell's mean power is {} W; expected > 0", p_ref));
  }
  return GreytoneMap(radar, p_ref, ref.greytone);
}

void greytones(std::span<const float> power_w, std::span<std::uint8_t> out, const GreytoneMap& map,
               std::span<const std::uint8_t> no_data, std::uint8_t no_data_greytone) {
  RIS_CHECK(out.size() == power_w.size());
  RIS_CHECK(no_data.empty() || no_data.size() == power_w.size());
  const auto n = static_cast<std::int64_t>(power_w.size());
  const float* p = power_w.data();
  const std::uint8_t* masked = no_data.empty() ? nullptr : no_data.data();
  std::uint8_t* g = out.data();
  // Each pixel is independent: any schedule gives the same bytes. Blocks of
  // pixels, so that each is one greytone_line call.
  constexpr std::int64_t kBlock = 4096;
  const std::int64_t blocks = (n + kBlock - 1) / kBlock;
#pragma omp parallel for schedule(static)
  for (std::int64_t blk = 0; blk < blocks; ++blk) {
    const auto i0 = static_cast<std::size_t>(blk * kBlock);
    const auto count = static_cast<std::size_t>(std::min(kBlock, n - blk * kBlock));
    greytone_line(map, p + i0, masked ? masked + i0 : nullptr, 0xff, count, g + i0,
                  no_data_greytone);
  }
}

}  // namespace ris
