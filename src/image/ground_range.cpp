#include "ris/image/ground_range.h"

#include "kernels/image/ground_range_kernels.h"
#include "kernels/simd/cpu.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "ris/util/error.h"
#include "ris/util/resource_guard.h"

namespace ris {

GroundRangeGrid ground_range_grid(const SlantRangeBins& bins, double altitude_m,
                                  double reference_height_m, double spacing_m) {
  RIS_CHECK(spacing_m > 0.0 && bins.count > 0);
  const double D = altitude_m - reference_height_m;
  if (!(D > 0.0)) {
    throw InputError("", "reference_height",
                     fmt::format("the ground-range reference height {:.1f} m is at or above the "
                                 "sensor altitude {:.1f} m",
                                 reference_height_m, altitude_m));
  }
  const auto ground = [D](double r) { return r > D ? std::sqrt(r * r - D * D) : 0.0; };
  GroundRangeGrid g;
  g.altitude_m = altitude_m;
  g.reference_height_m = reference_height_m;
  g.near_m = ground(bins.near_m);
  g.spacing_m = spacing_m;
  // Checked before the cast (ris/util/resource_guard.h): the spacing is the
  // azimuth line spacing, which a radar file may make tiny.
  g.count = std::max(1, static_cast<int>(checked_count(
                            std::ceil((ground(bins.far_m()) - g.near_m) / spacing_m), kMaxItems, "",
                            "azimuth_line_spacing", "ground-range pixels a line")));
  return g;
}

namespace {
// Fractional bin-centre coordinate of ground pixel j (bin k's centre is k).
std::vector<double> bin_positions(const SlantRangeBins& bins, const GroundRangeGrid& grid) {
  const double D = grid.altitude_m - grid.reference_height_m;
  std::vector<double> pos(static_cast<std::size_t>(grid.count));
  for (int j = 0; j < grid.count; ++j) {
    const double r = std::hypot(grid.centre_m(j), D);
    pos[static_cast<std::size_t>(j)] = (r - bins.near_m) / bins.bin_m - 0.5;
  }
  return pos;
}
}  // namespace

GroundRangeResampler::GroundRangeResampler(const SlantRangeBins& bins,
                                           const GroundRangeGrid& grid) {
  const std::vector<double> pos = bin_positions(bins, grid);
  const std::size_t cols = pos.size();
  k0_.assign(cols, 0);
  k1_.assign(cols, 0);
  nearest_.assign(cols, -1);
  weight_.assign(cols, 0.0);
  inside_.assign(cols, 0);
  const int last = bins.count - 1;
  for (std::size_t j = 0; j < cols; ++j) {
    const double x = pos[j];
    // The nearest bin (masks).
    const double r = std::round(x);
    if (r >= 0.0 && r < bins.count) nearest_[j] = static_cast<int>(r);
    if (x < -0.5 || x > last + 0.5) continue;  // beyond the swath: NaN
    // Half a bin at each end holds the end value.
    const double xc = std::clamp(x, 0.0, double(last));
    const int k = std::min(static_cast<int>(xc), std::max(last - 1, 0));
    k0_[j] = k;
    k1_[j] = std::min(k + 1, last);
    weight_[j] = xc - k;
    inside_[j] = 1;
  }
  // The slant range grows with the column, so the columns inside the swath
  // and those with a nearest bin are each one run: the loops below take no
  // per-pixel branch or select.
  const auto run = [&](auto in) {
    std::size_t begin = 0;
    while (begin < cols && !in(begin)) ++begin;
    std::size_t end = begin;
    while (end < cols && in(end)) ++end;
    for (std::size_t j = end; j < cols; ++j) RIS_CHECK(!in(j));
    return std::pair{begin, end};
  };
  std::tie(inside_begin_, inside_end_) = run([&](std::size_t j) { return inside_[j] != 0; });
  std::tie(nearest_begin_, nearest_end_) = run([&](std::size_t j) { return nearest_[j] >= 0; });
  bins_ = bins.count;
}

GroundRangeResampler::Columns GroundRangeResampler::columns_within(int first_bin,
                                                                   int end_bin) const {
  // k0 and k1 do not decrease along the inside run: two binary searches.
  const auto k0_begin = k0_.begin() + static_cast<std::ptrdiff_t>(inside_begin_);
  const auto k0_end = k0_.begin() + static_cast<std::ptrdiff_t>(inside_end_);
  const auto k1_begin = k1_.begin() + static_cast<std::ptrdiff_t>(inside_begin_);
  const auto k1_end = k1_.begin() + static_cast<std::ptrdiff_t>(inside_end_);
  Columns c;
  c.begin = static_cast<std::size_t>(std::lower_bound(k0_begin, k0_end, first_bin) - k0_.begin());
  c.end = static_cast<std::size_t>(std::lower_bound(k1_begin, k1_end, end_bin) - k1_.begin());
  if (c.end < c.begin) c.end = c.begin;
  return c;
}

void GroundRangeResampler::resample_line(const float* slant, float* out) const {
  resample_line(slant, out, Columns{inside_begin_, inside_end_});
}

void GroundRangeResampler::resample_line(const float* slant, float* out, Columns cols) const {
  RIS_CHECK(cols.begin >= inside_begin_ && cols.end <= inside_end_ && cols.begin <= cols.end);
  const std::int32_t* k0 = k0_.data();
  const std::int32_t* k1 = k1_.data();
  const double* w = weight_.data();
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  std::fill(out, out + cols.begin, kNaN);
  kernels::resample_columns(cpu_has_avx2(), slant, bins_, k0, k1, w, cols.begin, cols.end, out);
  std::fill(out + cols.end, out + weight_.size(), kNaN);
}

void GroundRangeResampler::nearest_line(const std::uint8_t* slant, std::uint8_t* out,
                                        std::uint8_t fill) const {
  const std::int32_t* nearest = nearest_.data();
  std::fill(out, out + nearest_begin_, fill);
  kernels::nearest_columns(cpu_has_avx2(), slant, bins_, nearest, nearest_begin_, nearest_end_,
                           out);
  std::fill(out + nearest_end_, out + nearest_.size(), fill);
}

std::vector<float> to_ground_range(std::span<const float> slant, int lines,
                                   const SlantRangeBins& bins, const GroundRangeGrid& grid) {
  RIS_CHECK(slant.size() == static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins.count));
  const GroundRangeResampler resampler(bins, grid);
  const std::size_t cols = static_cast<std::size_t>(grid.count);
  std::vector<float> out(static_cast<std::size_t>(lines) * cols);
#pragma omp parallel for schedule(static)
  for (int line = 0; line < lines; ++line) {
    resampler.resample_line(
        slant.data() + static_cast<std::size_t>(line) * static_cast<std::size_t>(bins.count),
        out.data() + static_cast<std::size_t>(line) * cols);
  }
  return out;
}

std::vector<std::uint8_t> to_ground_range_nearest(std::span<const std::uint8_t> slant, int lines,
                                                  const SlantRangeBins& bins,
                                                  const GroundRangeGrid& grid, std::uint8_t fill) {
  RIS_CHECK(slant.size() == static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins.count));
  const GroundRangeResampler resampler(bins, grid);
  const std::size_t cols = static_cast<std::size_t>(grid.count);
  std::vector<std::uint8_t> out(static_cast<std::size_t>(lines) * cols);
#pragma omp parallel for schedule(static)
  for (int line = 0; line < lines; ++line) {
    resampler.nearest_line(
        slant.data() + static_cast<std::size_t>(line) * static_cast<std::size_t>(bins.count),
        out.data() + static_cast<std::size_t>(line) * cols, fill);
  }
  return out;
}

}  // namespace ris
