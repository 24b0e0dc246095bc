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
  // Each bucket's first float by the thresholds (a binary search of 8 steps).
  bucket_.assign((kInfBits >> 16) + 1, 0);
  for (std::uint32_t b = 0; b < bucket_.size(); ++b) {
    const float p = as_float(b << 16);
    unsigned k = 0;
    for (unsigned step = 128; step > 0; step >>= 1) k = p >= threshold_[k + step] ? k + step : k;
    bucket_[b] = static_cast<std::uint8_t>(k);
  }
}

namespace {
bool valid_pixel(float p, std::span<const std::uint8_t> no_data, std::size_t i) {
  return std::isfinite(p) && p > 0.0f && (no_data.empty() || no_data[i] == 0);
}
}  // namespace

double median_valid_power_w(std::span<const float> power_w, std::span<const std::uint8_t> no_data) {
  RIS_CHECK(no_data.empty() || no_data.size() == power_w.size());
  // A parallel radix select (ris/util/float_select.h), not a sorted copy.
  const auto keep = [&](std::size_t i) { return valid_pixel(power_w[i], no_data, i); };
  const auto m = median_pair_float(power_w, keep);
  if (!m) return std::numeric_limits<double>::quiet_NaN();
  const double lower = m->first, upper = m->second;  // equal for an odd count
  if (lower == upper) return upper;
  return 0.5 * (lower + upper);
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
  // Each pixel is independent: any schedule gives the same bytes.
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const float p = power_w[k];
    const bool masked = std::isnan(p) || (!no_data.empty() && no_data[k] != 0);
    out[k] = masked ? no_data_greytone : map.quantised_fast(p);
  }
}

}  // namespace ris
