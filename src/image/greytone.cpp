#include "ris/image/greytone.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>
#include <vector>

#include "kernels/image/greytone_kernels.h"
#include "kernels/simd/cpu.h"
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
  const auto bits_of = [](float v) {
    std::uint32_t out = 0;
    std::memcpy(&out, &v, sizeof out);
    return out;
  };
  for (unsigned k = 1; k < 256; ++k) {
    std::uint32_t lo = 0, hi = kInfBits;  // quantised(lo) < k; hi: answer candidate
    if (quantised(double(as_float(hi))) < k) {
      threshold_[k] = std::numeric_limits<float>::infinity();
      continue;
    }
    // Start from equation 15 solved for G = k - 1/2 and widen a bracket
    // around it until it holds the threshold (a few steps instead of 31; the
    // bisection below decides exactly either way).
    const double estimate = std::pow(10.0, (k - 0.5 - offset_) / per_decade_);
    if (estimate > 0.0 && estimate < double(std::numeric_limits<float>::max())) {
      const std::uint32_t e = bits_of(static_cast<float>(estimate));
      for (std::uint32_t d = 16; d < kInfBits; d *= 4) {
        const std::uint32_t l = e > d ? e - d : 0, h = std::min(e + d, kInfBits);
        if ((l == 0 || quantised(double(as_float(l))) < k) && quantised(double(as_float(h))) >= k) {
          lo = l;
          hi = h;
          break;
        }
      }
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
  // Each bucket's first float's greytone (the number of thresholds at or
  // below it), and the most thresholds any bucket holds after its first float
  // (up to its last float, bits b << 16 | 0xffff). The positive floats grow
  // with their bits, so both counts only move up: one sweep.
  // (3 bytes of padding: the AVX2 kernel reads each entry as a 32-bit word.)
  constexpr std::uint32_t kBuckets = (kInfBits >> 16) + 1;
  bucket_.assign(kBuckets + 3, 0);
  max_steps_ = 0;
  unsigned first = 0, last = 0;  // thresholds at or below the bucket's first, last float
  for (std::uint32_t b = 0; b < kBuckets; ++b) {
    const float lo = as_float(b << 16);
    while (first < 255 && lo >= threshold_[first + 1]) ++first;
    bucket_[b] = static_cast<std::uint8_t>(first);
    if (b + 1 < kBuckets) {
      const float hi = as_float((b << 16) | 0xffffu);
      last = std::max(last, first);
      while (last < 255 && hi >= threshold_[last + 1]) ++last;
      max_steps_ = std::max(max_steps_, last - first);
    }
  }
  bucket_step_.assign(kBuckets, 0);
  for (std::uint32_t b = 0; b < kBuckets; ++b) {
    const unsigned g = bucket_[b];
    std::uint32_t step = 0x10000;  // no bits in the bucket reach (b << 16) + 0x10000
    if (g < 255) {
      const std::uint32_t t = bits_of(threshold_[g + 1]);
      if ((t >> 16) == b) step = t & 0xffffu;
    }
    bucket_step_[b] = static_cast<std::uint32_t>(g) << 17 | step;
  }
}

namespace {

// The median of the powers keep(i) accepts besides being finite and > 0 (a
// parallel radix select, ris/util/float_select.h, not a sorted copy); the
// mean of the two middle values for an even count.
template <typename Keep>
double median_positive_power(std::span<const float> power_w, Keep keep) {
  // Branch-free (& on bools), so that the median's keying loop vectorises.
  const float* const power = power_w.data();
  const auto valid = [=](std::size_t i) {
    const float p = power[i];
    return std::isfinite(p) & (p > 0.0f) & keep(i);
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
    kernels::quantise_one_step(cpu_has_avx2(), power_w, mask, mask_bits, n, out, no_data_greytone,
                               bucket_step_.data(), bucket_.data(), threshold_.data());
  } else {
    kernels::quantise_steps(power_w, mask, mask_bits, n, out, no_data_greytone, bucket_.data(),
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
  const std::uint8_t* const m = mask.data();
  return median_positive_power(power_w, [=](std::size_t i) { return (m[i] & mask_bits) == 0; });
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
