#include "ris/image/ground_range.h"

#include <fmt/format.h>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "ris/util/error.h"

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
  g.count = std::max(1, static_cast<int>(std::ceil((ground(bins.far_m()) - g.near_m) / spacing_m)));
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

namespace {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RIS_GROUND_RANGE_AVX2 1
// The vector kernels below use that a ground pixel is smaller than a slant
// bin's ground footprint (several columns a bin), so that a block of columns
// reads a few neighbouring bins: one load of the bins and a permutation
// within the register (hardware gathers were slower on this machine's EPYC:
// resample and nearest 1.4-1.6x slower than the scalar loops). A block whose
// bins do not fit one register takes the scalar loop.

// a + f (b - a) for four columns, in double (a lambda would not inherit the
// caller's target).
__attribute__((target("avx2"))) inline __m128 interpolate4(__m128 a4, __m128 b4, const double* w4) {
  const __m256d ad = _mm256_cvtps_pd(a4);
  return _mm256_cvtpd_ps(_mm256_add_pd(
      ad, _mm256_mul_pd(_mm256_loadu_pd(w4), _mm256_sub_pd(_mm256_cvtps_pd(b4), ad))));
}

// resample_line's loop eight columns at a time: the eight bins from the
// block's first k0 loaded, a and b picked by vpermps, then the scalar loop's
// operations in double (the floats widened exactly, no multiply-add: the
// AVX2 target has no FMA) and one rounding to float. The same bytes.
__attribute__((target("avx2"))) void resample_avx2(const float* slant, int bins,
                                                   const std::int32_t* k0, const std::int32_t* k1,
                                                   const double* w, std::size_t begin,
                                                   std::size_t end, float* out) {
  std::size_t j = begin;
  for (; j + 8 <= end; j += 8) {
    const std::int32_t base = k0[j];
    if (k1[j + 7] - base < 8 && base + 8 <= bins) {
      const __m256 v = _mm256_loadu_ps(slant + base);
      const __m256i off = _mm256_set1_epi32(base);
      const __m256 a = _mm256_permutevar8x32_ps(
          v, _mm256_sub_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(k0 + j)), off));
      const __m256 b = _mm256_permutevar8x32_ps(
          v, _mm256_sub_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(k1 + j)), off));
      const __m128 lo = interpolate4(_mm256_castps256_ps128(a), _mm256_castps256_ps128(b), w + j);
      const __m128 hi =
          interpolate4(_mm256_extractf128_ps(a, 1), _mm256_extractf128_ps(b, 1), w + j + 4);
      _mm256_storeu_ps(out + j, _mm256_set_m128(hi, lo));
    } else {
      for (std::size_t i = j; i < j + 8; ++i) {
        const float a = slant[k0[i]], b = slant[k1[i]];
        out[i] = static_cast<float>(a + w[i] * (double(b) - double(a)));
      }
    }
  }
  for (; j < end; ++j) {
    const float a = slant[k0[j]], b = slant[k1[j]];
    out[j] = static_cast<float>(a + w[j] * (double(b) - double(a)));
  }
}

// nearest_line's loop sixteen columns at a time: the sixteen bytes from the
// block's first nearest bin loaded, each column's picked by pshufb.
__attribute__((target("avx2"))) void nearest_avx2(const std::uint8_t* slant, int bins,
                                                  const std::int32_t* nearest, std::size_t begin,
                                                  std::size_t end, std::uint8_t* out) {
  std::size_t j = begin;
  for (; j + 16 <= end; j += 16) {
    const std::int32_t base = nearest[j];
    if (nearest[j + 15] - base < 16 && base + 16 <= bins) {
      const __m128i v = _mm_loadu_si128(reinterpret_cast<const __m128i*>(slant + base));
      const __m256i off = _mm256_set1_epi32(base);
      const __m256i o0 =
          _mm256_sub_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(nearest + j)), off);
      const __m256i o1 = _mm256_sub_epi32(
          _mm256_loadu_si256(reinterpret_cast<const __m256i*>(nearest + j + 8)), off);
      // Sixteen offsets (0..15) as bytes in column order (packus works per
      // 128-bit lane: the permute puts the halves back in order).
      const __m256i o16 = _mm256_permute4x64_epi64(_mm256_packus_epi32(o0, o1), 0xD8);
      const __m128i o8 =
          _mm_packus_epi16(_mm256_castsi256_si128(o16), _mm256_extracti128_si256(o16, 1));
      _mm_storeu_si128(reinterpret_cast<__m128i*>(out + j), _mm_shuffle_epi8(v, o8));
    } else {
      for (std::size_t i = j; i < j + 16; ++i) out[i] = slant[nearest[i]];
    }
  }
  for (; j < end; ++j) out[j] = slant[nearest[j]];
}
#endif

}  // namespace

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
  std::size_t j = cols.begin;
#ifdef RIS_GROUND_RANGE_AVX2
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) {
    resample_avx2(slant, bins_, k0, k1, w, j, cols.end, out);
    j = cols.end;
  }
#endif
  for (; j < cols.end; ++j) {
    const float a = slant[k0[j]], b = slant[k1[j]];
    out[j] = static_cast<float>(a + w[j] * (double(b) - double(a)));
  }
  std::fill(out + cols.end, out + weight_.size(), kNaN);
}

void GroundRangeResampler::nearest_line(const std::uint8_t* slant, std::uint8_t* out,
                                        std::uint8_t fill) const {
  const std::int32_t* nearest = nearest_.data();
  std::fill(out, out + nearest_begin_, fill);
  std::size_t j = nearest_begin_;
#ifdef RIS_GROUND_RANGE_AVX2
  static const bool avx2 = __builtin_cpu_supports("avx2");
  if (avx2) {
    nearest_avx2(slant, bins_, nearest, j, nearest_end_, out);
    j = nearest_end_;
  }
#endif
  for (; j < nearest_end_; ++j) out[j] = slant[nearest[j]];
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
