#include "ris/image/slar_azimuth_integrator.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "kernels/image/azimuth_kernels.h"
#include "kernels/simd/cpu.h"
#include "ris/util/error.h"

namespace ris {

SlarAzimuthIntegrator::SlarAzimuthIntegrator(const SlarImagingParams& p, double line_spacing_m,
                                             int lines, int bins, int bin_begin, int bin_end)
    : lines_(lines), bin0_(bin_begin) {
  if (bin_end < 0) bin_end = bins;
  RIS_CHECK(lines > 0 && bins > 0 && 0 <= bin_begin && bin_begin < bin_end && bin_end <= bins);
  bins_ = bin_end - bin_begin;
  threaded_ = bins_ == bins;
  half_.resize(static_cast<std::size_t>(bins_));
  double half_max = 0.0;
  for (int b = 0; b < bins_; ++b) {
    // The image's bin number: the same footprint as the whole integrator's.
    const int image_bin = bin0_ + b;
    const double half =
        p.azimuth_window_lines > 0.0
            ? 0.5 * p.azimuth_window_lines
            : 0.5 * slar_footprint_m(p.range.centre_m(image_bin), p.azimuth_beamwidth_rad) /
                  line_spacing_m;
    half_[static_cast<std::size_t>(b)] = half;
    if (std::isfinite(half)) half_max = std::max(half_max, half);
  }
  // A footprint longer than the image reaches every line anyway.
  margin_ = static_cast<int>(std::min(std::ceil(half_max), double(lines))) + 2;
  extent_.resize(static_cast<std::size_t>(lines));
  // Running-sum row 0: nothing summed yet.
  const std::size_t n = static_cast<std::size_t>(bins);
  cum_.assign(n, 0.0);
  cum_area_.assign(n, 0.0);
  cum_data_.assign(n, 0);
  cum_visible_.assign(n, 0);
  cum_layover_.assign(n, 0);
}

std::pair<int, int> SlarAzimuthIntegrator::active_bins(int k) const {
  // Pixel k reads the running sums of lines within ceil(half) + 1 < M of it
  // (emit_pixel: the integral's rows and the mask's strips); every one of
  // those lines is pushed when k is emitted (lines_ready).
  const int j0 = std::max(0, k - margin_), j1 = std::min(pushed_ - 1, k + margin_);
  int lo = bins_, hi = 0;
  for (int j = j0; j <= j1; ++j) {
    const auto [l, h] = extent_[static_cast<std::size_t>(j)];
    if (l < h) {
      lo = std::min(lo, l);
      hi = std::max(hi, h);
    }
  }
  return lo < hi ? std::pair{lo, hi} : std::pair{0, 0};
}

std::size_t SlarAzimuthIntegrator::row(int cum_index) const {
  return static_cast<std::size_t>(cum_index - base_) * static_cast<std::size_t>(bins_);
}

void SlarAzimuthIntegrator::push(const SlarLineProfiles& prof, int count) {
  RIS_CHECK(prof.bins >= bin0_ + bins_ && count >= 0 && pushed_ + count <= lines_);
  RIS_CHECK(!threaded_ || prof.bins == bins_);
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
  // arithmetic of a pixel does not depend on the thread count), and finds
  // each line's extent within them; the extents are merged after.
  const int max_threads = threaded_ ? omp_get_max_threads() : 1;
  part_extent_.assign(static_cast<std::size_t>(max_threads) * static_cast<std::size_t>(count),
                      {bins_, 0});
#pragma omp parallel if (threaded_)
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    const int b0 = static_cast<int>(std::int64_t(bins_) * t / nt);
    const int b1 = static_cast<int>(std::int64_t(bins_) * (t + 1) / nt);
    for (int j = pushed_; j < pushed_ + count; ++j) {
      const std::size_t in = prof.index(j, bin0_) + static_cast<std::size_t>(b0);
      const std::size_t prev = row(j) + static_cast<std::size_t>(b0);
      const std::size_t next = row(j + 1) + static_cast<std::size_t>(b0);
      const auto [lo, hi] = kernels::push_row(
          b1 - b0, prof.touch.data() + in, prof.power_w.data() + in, prof.area_m2.data() + in,
          {cum_.data() + prev, cum_area_.data() + prev, cum_data_.data() + prev,
           cum_visible_.data() + prev, cum_layover_.data() + prev},
          {cum_.data() + next, cum_area_.data() + next, cum_data_.data() + next,
           cum_visible_.data() + next, cum_layover_.data() + next});
      if (lo < hi) {
        part_extent_[static_cast<std::size_t>(t) * static_cast<std::size_t>(count) +
                     static_cast<std::size_t>(j - pushed_)] = {b0 + lo, b0 + hi};
      }
    }
  }
  for (int k = 0; k < count; ++k) {
    int lo = bins_, hi = 0;
    for (int t = 0; t < max_threads; ++t) {
      const auto [l, h] =
          part_extent_[static_cast<std::size_t>(t) * static_cast<std::size_t>(count) +
                       static_cast<std::size_t>(k)];
      lo = std::min(lo, l);
      hi = std::max(hi, h);
    }
    extent_[static_cast<std::size_t>(pushed_ + k)] = lo < hi ? std::pair{lo, hi} : std::pair{0, 0};
  }
  pushed_ += count;
}

int SlarAzimuthIntegrator::lines_ready() const {
  if (pushed_ == lines_) return lines_ - emitted_;
  // Line k needs running sums up to index k + M (see the header).
  return std::max(0, pushed_ - margin_ + 1 - emitted_);
}

void SlarAzimuthIntegrator::emit(int count, float* mean_power_w, float* area_m2, std::uint8_t* mask,
                                 std::size_t row_stride) {
  RIS_CHECK(count >= 0 && count <= lines_ready());
  const int bins = bins_;
  const std::size_t stride = row_stride > 0 ? row_stride : static_cast<std::size_t>(bins);
  const kernels::EmitRows rows{cum_.data(),
                               cum_area_.data(),
                               cum_data_.data(),
                               cum_visible_.data(),
                               cum_layover_.data(),
                               half_.data(),
                               base_,
                               bins,
                               lines_};
  const int first = emitted_;
  static const bool avx2 = cpu_has_avx2();
  static const bool avx512 = cpu_has_avx512();
  // Dynamic blocks of lines (see render_slar); each line is independent.
#pragma omp parallel for schedule(dynamic, 16) if (threaded_)
  for (int k = first; k < first + count; ++k) {
    const std::size_t out = static_cast<std::size_t>(k - first) * stride;
    float* const power = mean_power_w + out;
    float* const area = area_m2 + out;
    std::uint8_t* const m = mask + out;
    // Outside the data extents of the lines within M of line k the
    // footprint holds no data (see active_bins): the pixel's rule gives
    // +0 W, +0 m^2 and kNoData there, written directly. The bins computed
    // start and end on a multiple of four, as the vector blocks.
    const auto [lo, hi] = active_bins(k);
    const int begin = lo / 4 * 4;
    const int end = std::min(bins, (hi + 3) / 4 * 4);
    std::fill(power, power + begin, 0.0f);
    std::fill(area, area + begin, 0.0f);
    std::fill(m, m + begin, pixel_flag::kNoData);
    kernels::emit_line(rows, k, begin, end, power, area, m, avx2, avx512);
    std::fill(power + end, power + bins, 0.0f);
    std::fill(area + end, area + bins, 0.0f);
    std::fill(m + end, m + bins, pixel_flag::kNoData);
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
