#include "ris/image/ground_range.h"

#include <fmt/format.h>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

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
  while (nearest_gather_cols_ < cols && nearest_[nearest_gather_cols_] <= bins.count - 4)
    ++nearest_gather_cols_;
}

namespace {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RIS_GROUND_RANGE_AVX2 1
// a + w (b - a) of four float pairs in double, rounded to float.
__attribute__((target("avx2"))) inline __m128 interpolate4(__m128 a4, __m128 b4, const double* w4) {
  const __m256d ad = _mm256_cvtps_pd(a4), bd = _mm256_cvtps_pd(b4);
  return _mm256_cvtpd_ps(
      _mm256_add_pd(ad, _mm256_mul_pd(_mm256_loadu_pd(w4), _mm256_sub_pd(bd, ad))));
}

// resample_line eight pixels at a time: AVX2 gathers of the two bins, the
// interpolation in double with separate multiply and add (as the scalar
// loop: the same bytes), NaN beyond the swath. Returns the pixels done.
__attribute__((target("avx2"))) std::size_t resample_avx2(const float* slant, float* out,
                                                          std::size_t cols, const std::int32_t* k0,
                                                          const std::int32_t* k1, const double* w,
                                                          const std::uint8_t* inside) {
  const __m256 nan = _mm256_set1_ps(std::numeric_limits<float>::quiet_NaN());
  std::size_t j = 0;
  for (; j + 8 <= cols; j += 8) {
    const __m256 a =
        _mm256_i32gather_ps(slant, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(k0 + j)), 4);
    const __m256 b =
        _mm256_i32gather_ps(slant, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(k1 + j)), 4);
    const __m128 lo = interpolate4(_mm256_castps256_ps128(a), _mm256_castps256_ps128(b), w + j);
    const __m128 hi =
        interpolate4(_mm256_extractf128_ps(a, 1), _mm256_extractf128_ps(b, 1), w + j + 4);
    std::uint64_t in8 = 0;
    std::memcpy(&in8, inside + j, sizeof in8);
    const __m256i in = _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(in8)));
    const __m256 outside = _mm256_castsi256_ps(_mm256_cmpeq_epi32(in, _mm256_setzero_si256()));
    _mm256_storeu_ps(out + j, _mm256_blendv_ps(_mm256_set_m128(hi, lo), nan, outside));
  }
  return j;
}

// nearest_line over its first `cols` pixels (each nearest bin at most
// bins - 4, so the 4-byte gathers stay in the line), eight at a time.
__attribute__((target("avx2"))) std::size_t nearest_avx2(const std::uint8_t* slant,
                                                         std::uint8_t* out, std::size_t cols,
                                                         const std::int32_t* nearest,
                                                         std::uint8_t fill) {
  const __m256i zero = _mm256_setzero_si256();
  const __m256i byte = _mm256_set1_epi32(0xff);
  const __m256i fill8 = _mm256_set1_epi32(fill);
  std::size_t j = 0;
  for (; j + 8 <= cols; j += 8) {
    const __m256i k = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(nearest + j));
    const __m256i none = _mm256_cmpgt_epi32(zero, k);  // -1: beyond the swath
    const __m256i v = _mm256_and_si256(
        _mm256_i32gather_epi32(reinterpret_cast<const int*>(slant), _mm256_max_epi32(k, zero), 1),
        byte);
    const __m256i g = _mm256_blendv_epi8(v, fill8, none);
    const __m128i g16 = _mm_packus_epi32(_mm256_castsi256_si128(g), _mm256_extracti128_si256(g, 1));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out + j), _mm_packus_epi16(g16, g16));
  }
  return j;
}

bool have_avx2() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}
#endif

}  // namespace

void GroundRangeResampler::resample_line(const float* slant, float* out) const {
  const std::size_t cols = weight_.size();
  const std::int32_t* k0 = k0_.data();
  const std::int32_t* k1 = k1_.data();
  const double* w = weight_.data();
  const std::uint8_t* inside = inside_.data();
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  std::size_t j = 0;
#ifdef RIS_GROUND_RANGE_AVX2
  if (have_avx2()) j = resample_avx2(slant, out, cols, k0, k1, w, inside);
#endif
  for (; j < cols; ++j) {
    const float a = slant[k0[j]], b = slant[k1[j]];
    const auto v = static_cast<float>(a + w[j] * (double(b) - double(a)));
    out[j] = inside[j] ? v : kNaN;
  }
}

void GroundRangeResampler::nearest_line(const std::uint8_t* slant, std::uint8_t* out,
                                        std::uint8_t fill) const {
  const std::size_t cols = nearest_.size();
  std::size_t j = 0;
#ifdef RIS_GROUND_RANGE_AVX2
  if (have_avx2()) j = nearest_avx2(slant, out, nearest_gather_cols_, nearest_.data(), fill);
#endif
  for (; j < cols; ++j) {
    const std::int32_t k = nearest_[j];
    out[j] = k >= 0 ? slant[k] : fill;
  }
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
