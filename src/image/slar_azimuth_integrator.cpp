#include "ris/image/slar_azimuth_integrator.h"

#include <omp.h>

#include <algorithm>
#include <cmath>

#include "ris/util/error.h"

namespace ris {

SlarAzimuthIntegrator::SlarAzimuthIntegrator(const SlarImagingParams& p, double line_spacing_m,
                                             int lines, int bins)
    : lines_(lines), bins_(bins), half_(static_cast<std::size_t>(bins)) {
  RIS_CHECK(lines > 0 && bins > 0);
  double half_max = 0.0;
  for (int b = 0; b < bins; ++b) {
    const double half =
        p.azimuth_window_lines > 0.0
            ? 0.5 * p.azimuth_window_lines
            : 0.5 * slar_footprint_m(p.range.centre_m(b), p.azimuth_beamwidth_rad) / line_spacing_m;
    half_[static_cast<std::size_t>(b)] = half;
    if (std::isfinite(half)) half_max = std::max(half_max, half);
  }
  // A footprint longer than the image reaches every line anyway.
  margin_ = static_cast<int>(std::min(std::ceil(half_max), double(lines))) + 2;
  // Running-sum row 0: nothing summed yet.
  const std::size_t n = static_cast<std::size_t>(bins);
  cum_.assign(n, 0.0);
  cum_area_.assign(n, 0.0);
  cum_data_.assign(n, 0);
  cum_visible_.assign(n, 0);
  cum_layover_.assign(n, 0);
}

std::size_t SlarAzimuthIntegrator::row(int cum_index) const {
  return static_cast<std::size_t>(cum_index - base_) * static_cast<std::size_t>(bins_);
}

void SlarAzimuthIntegrator::push(const SlarLineProfiles& prof, int count) {
  RIS_CHECK(prof.bins == bins_ && count >= 0 && pushed_ + count <= lines_);
  RIS_CHECK(prof.line0 <= pushed_ && pushed_ + count <= prof.line0 + prof.lines);
  if (count == 0) return;
  const std::size_t n =
      static_cast<std::size_t>(pushed_ + count + 1 - base_) * static_cast<std::size_t>(bins_);
  cum_.resize(n);
  cum_area_.resize(n);
  cum_data_.resize(n);
  cum_visible_.resize(n);
  cum_layover_.resize(n);
  // Each thread sums its own bins over the lines, in line order (the
  // arithmetic of a pixel does not depend on the thread count).
#pragma omp parallel
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    const int b0 = static_cast<int>(std::int64_t(bins_) * t / nt);
    const int b1 = static_cast<int>(std::int64_t(bins_) * (t + 1) / nt);
    for (int j = pushed_; j < pushed_ + count; ++j) {
      const std::size_t in = prof.index(j, 0), prev = row(j), next = row(j + 1);
      for (int b = b0; b < b1; ++b) {
        const std::size_t bb = static_cast<std::size_t>(b);
        const std::size_t k = in + bb;
        const std::uint8_t touch = prof.touch[k];
        cum_[next + bb] = cum_[prev + bb] + double(prof.power_w[k]);
        cum_area_[next + bb] = cum_area_[prev + bb] + double(prof.area_m2[k]);
        cum_data_[next + bb] = cum_data_[prev + bb] + ((touch & slar_touch::kData) ? 1 : 0);
        cum_visible_[next + bb] =
            cum_visible_[prev + bb] + ((touch & slar_touch::kVisible) ? 1 : 0);
        cum_layover_[next + bb] =
            cum_layover_[prev + bb] + ((touch & slar_touch::kLayover) ? 1 : 0);
      }
    }
  }
  pushed_ += count;
}

int SlarAzimuthIntegrator::lines_ready() const {
  if (pushed_ == lines_) return lines_ - emitted_;
  // Line k needs running sums up to index k + M (see the header).
  return std::max(0, pushed_ - margin_ + 1 - emitted_);
}

void SlarAzimuthIntegrator::emit(int count, float* mean_power_w, float* area_m2,
                                 std::uint8_t* mask) {
  RIS_CHECK(count >= 0 && count <= lines_ready());
  const int n = lines_;
  const int bins = bins_;
  // Integral of the profile from -1/2 to x (line units), clamped.
  const auto integral = [&](const std::vector<double>& c, std::size_t bb, double x) {
    const double y = std::clamp(x + 0.5, 0.0, double(n));
    const int i = std::min(static_cast<int>(y), n - 1);
    const double f = y - i;
    const std::size_t a = row(i) + bb, b = row(i + 1) + bb;
    return c[a] + f * (c[b] - c[a]);
  };
  const int first = emitted_;
#pragma omp parallel for schedule(static)
  for (int k = first; k < first + count; ++k) {
    const std::size_t out = static_cast<std::size_t>(k - first) * static_cast<std::size_t>(bins);
    for (int b = 0; b < bins; ++b) {
      const std::size_t bb = static_cast<std::size_t>(b);
      const double half = half_[bb];
      const double a = k - half, e = k + half;
      mean_power_w[out + bb] = static_cast<float>(integral(cum_, bb, e) - integral(cum_, bb, a));
      area_m2[out + bb] =
          static_cast<float>(integral(cum_area_, bb, e) - integral(cum_area_, bb, a));
      // Lines whose strip overlaps the footprint: j + 1/2 > a and j - 1/2 < e.
      const int j_lo = std::max(0, static_cast<int>(std::floor(a - 0.5)) + 1);
      const int j_hi = std::min(n - 1, static_cast<int>(std::ceil(e + 0.5)) - 1);
      const std::size_t lo = row(j_lo) + bb, hi = row(j_hi + 1) + bb;
      const int data = cum_data_[hi] - cum_data_[lo];
      const int visible = cum_visible_[hi] - cum_visible_[lo];
      const int layover = cum_layover_[hi] - cum_layover_[lo];
      std::uint8_t m = 0;
      if (data == 0) m |= pixel_flag::kNoData;
      if (data > 0 && visible == 0) m |= pixel_flag::kShadow;
      if (layover > 0) m |= pixel_flag::kLayover;
      mask[out + bb] = m;
    }
  }
  emitted_ += count;
  // Drop the running sums no later line needs (indices below emitted_ - M).
  const int keep_from = std::max(base_, std::min(emitted_ - margin_, pushed_));
  if (keep_from > base_) {
    const auto drop = static_cast<std::ptrdiff_t>(row(keep_from));
    cum_.erase(cum_.begin(), cum_.begin() + drop);
    cum_area_.erase(cum_area_.begin(), cum_area_.begin() + drop);
    cum_data_.erase(cum_data_.begin(), cum_data_.begin() + drop);
    cum_visible_.erase(cum_visible_.begin(), cum_visible_.begin() + drop);
    cum_layover_.erase(cum_layover_.begin(), cum_layover_.begin() + drop);
    base_ = keep_from;
  }
}

}  // namespace ris
