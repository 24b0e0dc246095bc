// The azimuth integrator's kernels (kernels/image/azimuth_kernels.h), moved
// from image/slar_azimuth_integrator.cpp unchanged.
#include "kernels/image/azimuth_kernels.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "ris/image/slar_image.h"
#include "ris/kernels/vector_clones.h"

// GCC 12's AVX-512 intrinsics pass _mm512_undefined_*() as the masked-off
// source of the unmasked forms, which -Wmaybe-uninitialized reports once they
// are inlined (GCC bug 105593, fixed in GCC 13): a false positive. (Before
// the intrinsics' headers, whose lines the warning points at.)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "kernels/simd/avx512.h"

namespace ris::kernels {

namespace {

// Running-sum row j + 1 = row j + line j's profile, over n bins. A function
// of its own with restrict-qualified arrays so that it vectorises (the
// member loop did not: the byte loads may alias the rows); the same
// additions, so the same bytes.
RIS_VECTOR_CLONES void push_row_kernel(
    int n, const std::uint8_t* __restrict touch, const float* __restrict power,
    const float* __restrict area, const double* __restrict p_power, const double* __restrict p_area,
    const int* __restrict p_data, const int* __restrict p_visible, const int* __restrict p_layover,
    double* __restrict n_power, double* __restrict n_area, int* __restrict n_data,
    int* __restrict n_visible, int* __restrict n_layover) {
  for (int b = 0; b < n; ++b) {
    const int t = touch[b];
    n_power[b] = p_power[b] + double(power[b]);
    n_area[b] = p_area[b] + double(area[b]);
    n_data[b] = p_data[b] + ((t & slar_touch::kData) != 0);
    n_visible[b] = p_visible[b] + ((t & slar_touch::kVisible) != 0);
    n_layover[b] = p_layover[b] + ((t & slar_touch::kLayover) != 0);
  }
}

// The bins [lo, hi) of a profile row outside which its touch, power and
// area bits are all zero ({0, 0} when all are): from both ends eight bins
// at a time as 64-bit words (a loop over every bin with min / max
// reductions did not vectorise); the row is in L1 after push_row_kernel.
std::pair<int, int> row_extent(int n, const std::uint8_t* touch, const float* power,
                               const float* area) {
  const auto word = [](const void* at) {
    std::uint64_t w = 0;
    std::memcpy(&w, at, sizeof w);
    return w;
  };
  const auto zero8 = [&](int b) {
    const float* p = power + b;
    const float* a = area + b;
    return (word(touch + b) | word(p) | word(p + 2) | word(p + 4) | word(p + 6) | word(a) |
            word(a + 2) | word(a + 4) | word(a + 6)) == 0;
  };
  const auto zero1 = [&](int b) {
    std::uint32_t p = 0, a = 0;
    std::memcpy(&p, power + b, sizeof p);
    std::memcpy(&a, area + b, sizeof a);
    return (touch[b] | p | a) == 0;
  };
  int lo = 0;
  while (lo + 8 <= n && zero8(lo)) lo += 8;
  while (lo < n && zero1(lo)) ++lo;
  if (lo == n) return {0, 0};
  int hi = n;
  while (hi - 8 >= lo && zero8(hi - 8)) hi -= 8;
  while (zero1(hi - 1)) --hi;  // stops at lo + 1 at the latest
  return {lo, hi};
}

}  // namespace

// push_row_kernel on a row of running sums; returns row_extent.
std::pair<int, int> push_row(int n, const std::uint8_t* touch, const float* power,
                             const float* area, const CumRow& prev, const CumRow& next) {
  push_row_kernel(n, touch, power, area, prev.power, prev.area, prev.data, prev.visible,
                  prev.layover, next.power, next.area, next.data, next.visible, next.layover);
  return row_extent(n, touch, power, area);
}

namespace {

// Pixel (line k, bin b) of emit(): the profile integrated over
// [k - half, k + half] by the running sums, and the mask from the lines whose
// strip overlaps it.
inline void emit_pixel(const EmitRows& r, int k, int b, float* power, float* area,
                       std::uint8_t* mask) {
  const int n = r.lines;
  const std::size_t bb = static_cast<std::size_t>(b);
  // Integral of the profile from -1/2 to x (line units), clamped.
  const auto integral = [&](const double* c, double x) {
    const double y = std::clamp(x + 0.5, 0.0, double(n));
    const int i = std::min(static_cast<int>(y), n - 1);
    const double f = y - i;
    const std::size_t lo = r.row(i) + bb, hi = r.row(i + 1) + bb;
    return c[lo] + f * (c[hi] - c[lo]);
  };
  const double half = r.half[bb];
  const double a = k - half, e = k + half;
  power[bb] = static_cast<float>(integral(r.cum, e) - integral(r.cum, a));
  area[bb] = static_cast<float>(integral(r.cum_area, e) - integral(r.cum_area, a));
  // Lines whose strip overlaps the footprint: j + 1/2 > a and j - 1/2 < e.
  const int j_lo = std::max(0, static_cast<int>(std::floor(a - 0.5)) + 1);
  const int j_hi = std::min(n - 1, static_cast<int>(std::ceil(e + 0.5)) - 1);
  const std::size_t lo = r.row(j_lo) + bb, hi = r.row(j_hi + 1) + bb;
  const int data = r.cum_data[hi] - r.cum_data[lo];
  const int visible = r.cum_visible[hi] - r.cum_visible[lo];
  const int layover = r.cum_layover[hi] - r.cum_layover[lo];
  std::uint8_t m = 0;
  if (data == 0) m |= pixel_flag::kNoData;
  if (data > 0 && visible == 0) m |= pixel_flag::kShadow;
  if (layover > 0) m |= pixel_flag::kLayover;
  mask[bb] = m;
}

#ifdef RIS_HAVE_AVX512_KERNELS

// Helpers of emit_line_avx2 (lambdas would not inherit its target).
__attribute__((target("avx2"))) inline bool all_lanes_equal(__m128i v) {
  return _mm_movemask_epi8(_mm_cmpeq_epi32(v, _mm_shuffle_epi32(v, 0))) == 0xffff;
}
// c[at] + f (c[at + stride] - c[at]) for four neighbouring bins.
__attribute__((target("avx2"))) inline __m256d integral4(const double* c, std::size_t at,
                                                         std::size_t stride, __m256d f) {
  const __m256d c0 = _mm256_loadu_pd(c + at), c1 = _mm256_loadu_pd(c + at + stride);
  return _mm256_add_pd(c0, _mm256_mul_pd(f, _mm256_sub_pd(c1, c0)));
}
__attribute__((target("avx2"))) inline __m128i count4(const int* c, std::size_t lo,
                                                      std::size_t hi) {
  return _mm_sub_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(c + hi)),
                       _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + lo)));
}

// emit()'s per-pixel rule four bins at a time. The footprint grows slowly
// with range, so four neighbouring bins almost always read the same rows of
// the running sums (the same i at both window ends and the same line
// strips): those take contiguous vector loads; the arithmetic is the scalar
// rule's, in double with separate multiplies and adds, so the same bytes.
// A block whose rows differ takes emit_pixel bin by bin. Bins [begin, end);
// returns the first bin not done (the last (end - begin) % 4 are left to the
// caller).
__attribute__((target("avx2"))) int emit_line_avx2(const EmitRows& r, int k, int begin, int end,
                                                   float* power, float* area, std::uint8_t* mask) {
  const __m256d zero = _mm256_setzero_pd(), half_line = _mm256_set1_pd(0.5);
  const __m256d lines_d = _mm256_set1_pd(double(r.lines));
  const __m128i last = _mm_set1_epi32(r.lines - 1);
  const __m256d kd = _mm256_set1_pd(double(k));
  const std::size_t stride = static_cast<std::size_t>(r.bins);
  int b = begin;
  for (; b + 4 <= end; b += 4) {
    const __m256d half = _mm256_loadu_pd(r.half + b);
    const __m256d a = _mm256_sub_pd(kd, half), e = _mm256_add_pd(kd, half);
    // std::clamp(x + 1/2, 0, n): max(0, .) keeps -0 as clamp does, then min(n, .).
    const __m256d ya = _mm256_min_pd(lines_d, _mm256_max_pd(zero, _mm256_add_pd(a, half_line)));
    const __m256d ye = _mm256_min_pd(lines_d, _mm256_max_pd(zero, _mm256_add_pd(e, half_line)));
    const __m128i ia = _mm_min_epi32(_mm256_cvttpd_epi32(ya), last);
    const __m128i ie = _mm_min_epi32(_mm256_cvttpd_epi32(ye), last);
    // Lines whose strip overlaps the footprint (see the scalar rule).
    const __m128i j_lo = _mm_max_epi32(
        _mm_setzero_si128(),
        _mm_add_epi32(_mm256_cvttpd_epi32(_mm256_floor_pd(_mm256_sub_pd(a, half_line))),
                      _mm_set1_epi32(1)));
    const __m128i j_hi = _mm_min_epi32(
        last, _mm_sub_epi32(_mm256_cvttpd_epi32(_mm256_ceil_pd(_mm256_add_pd(e, half_line))),
                            _mm_set1_epi32(1)));
    if (!(all_lanes_equal(ia) && all_lanes_equal(ie) && all_lanes_equal(j_lo) &&
          all_lanes_equal(j_hi))) {
      // The rows differ within the block: the scalar rule, bin by bin.
      for (int bb = b; bb < b + 4; ++bb) emit_pixel(r, k, bb, power, area, mask);
      continue;
    }
    const std::size_t ra = r.row(_mm_cvtsi128_si32(ia)) + static_cast<std::size_t>(b);
    const std::size_t re = r.row(_mm_cvtsi128_si32(ie)) + static_cast<std::size_t>(b);
    const __m256d fa = _mm256_sub_pd(ya, _mm256_cvtepi32_pd(ia));
    const __m256d fe = _mm256_sub_pd(ye, _mm256_cvtepi32_pd(ie));
    _mm_storeu_ps(power + b, _mm256_cvtpd_ps(_mm256_sub_pd(integral4(r.cum, re, stride, fe),
                                                           integral4(r.cum, ra, stride, fa))));
    _mm_storeu_ps(area + b, _mm256_cvtpd_ps(_mm256_sub_pd(integral4(r.cum_area, re, stride, fe),
                                                          integral4(r.cum_area, ra, stride, fa))));
    const std::size_t lo = r.row(_mm_cvtsi128_si32(j_lo)) + static_cast<std::size_t>(b);
    const std::size_t hi = r.row(_mm_cvtsi128_si32(j_hi) + 1) + static_cast<std::size_t>(b);
    const __m128i data = count4(r.cum_data, lo, hi), visible = count4(r.cum_visible, lo, hi),
                  layover = count4(r.cum_layover, lo, hi);
    const __m128i z = _mm_setzero_si128();
    const __m128i no_data = _mm_cmpeq_epi32(data, z);
    const __m128i shadow = _mm_and_si128(_mm_cmpgt_epi32(data, z), _mm_cmpeq_epi32(visible, z));
    const __m128i laid = _mm_cmpgt_epi32(layover, z);
    const __m128i m =
        _mm_or_si128(_mm_or_si128(_mm_and_si128(no_data, _mm_set1_epi32(pixel_flag::kNoData)),
                                  _mm_and_si128(shadow, _mm_set1_epi32(pixel_flag::kShadow))),
                     _mm_and_si128(laid, _mm_set1_epi32(pixel_flag::kLayover)));
    const __m128i m16 = _mm_packus_epi32(m, m);
    const int m8 = _mm_cvtsi128_si32(_mm_packus_epi16(m16, m16));
    std::memcpy(mask + b, &m8, 4);
  }
  return b;
}

// emit_line_avx2 eight bins at a time with AVX-512 (the same operations in
// the same order, eight lanes; the mask bytes from mask registers): about
// half the instructions per bin. The caller finishes with emit_line_avx2's
// quads and emit_pixel.
RIS_AVX512_KERNEL inline bool all_lanes_equal8(__m256i v) {
  return _mm256_cmpeq_epi32_mask(v, _mm256_permutevar8x32_epi32(v, _mm256_setzero_si256())) == 0xff;
}
RIS_AVX512_KERNEL inline __m512d integral8(const double* c, std::size_t at, std::size_t stride,
                                           __m512d f) {
  const __m512d c0 = _mm512_loadu_pd(c + at), c1 = _mm512_loadu_pd(c + at + stride);
  return _mm512_add_pd(c0, _mm512_mul_pd(f, _mm512_sub_pd(c1, c0)));
}
RIS_AVX512_KERNEL inline __m256i count8(const int* c, std::size_t lo, std::size_t hi) {
  return _mm256_sub_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(c + hi)),
                          _mm256_loadu_si256(reinterpret_cast<const __m256i*>(c + lo)));
}

RIS_AVX512_KERNEL int emit_line_avx512(const EmitRows& r, int k, int begin, int end, float* power,
                                       float* area, std::uint8_t* mask) {
  const __m512d zero = _mm512_setzero_pd(), half_line = _mm512_set1_pd(0.5);
  const __m512d lines_d = _mm512_set1_pd(double(r.lines));
  const __m256i last = _mm256_set1_epi32(r.lines - 1);
  const __m512d kd = _mm512_set1_pd(double(k));
  const std::size_t stride = static_cast<std::size_t>(r.bins);
  constexpr int kFloor = _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC;
  constexpr int kCeil = _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC;
  int b = begin;
  for (; b + 8 <= end; b += 8) {
    const __m512d half = _mm512_loadu_pd(r.half + b);
    const __m512d a = _mm512_sub_pd(kd, half), e = _mm512_add_pd(kd, half);
    const __m512d ya = _mm512_min_pd(lines_d, _mm512_max_pd(zero, _mm512_add_pd(a, half_line)));
    const __m512d ye = _mm512_min_pd(lines_d, _mm512_max_pd(zero, _mm512_add_pd(e, half_line)));
    const __m256i ia = _mm256_min_epi32(_mm512_cvttpd_epi32(ya), last);
    const __m256i ie = _mm256_min_epi32(_mm512_cvttpd_epi32(ye), last);
    const __m256i j_lo = _mm256_max_epi32(
        _mm256_setzero_si256(), _mm256_add_epi32(_mm512_cvttpd_epi32(_mm512_roundscale_pd(
                                                     _mm512_sub_pd(a, half_line), kFloor)),
                                                 _mm256_set1_epi32(1)));
    const __m256i j_hi = _mm256_min_epi32(
        last, _mm256_sub_epi32(
                  _mm512_cvttpd_epi32(_mm512_roundscale_pd(_mm512_add_pd(e, half_line), kCeil)),
                  _mm256_set1_epi32(1)));
    if (!(all_lanes_equal8(ia) && all_lanes_equal8(ie) && all_lanes_equal8(j_lo) &&
          all_lanes_equal8(j_hi))) {
      for (int bb = b; bb < b + 8; ++bb) emit_pixel(r, k, bb, power, area, mask);
      continue;
    }
    const std::size_t ra = r.row(_mm256_cvtsi256_si32(ia)) + static_cast<std::size_t>(b);
    const std::size_t re = r.row(_mm256_cvtsi256_si32(ie)) + static_cast<std::size_t>(b);
    const __m512d fa = _mm512_sub_pd(ya, _mm512_cvtepi32_pd(ia));
    const __m512d fe = _mm512_sub_pd(ye, _mm512_cvtepi32_pd(ie));
    _mm256_storeu_ps(power + b, _mm512_cvtpd_ps(_mm512_sub_pd(integral8(r.cum, re, stride, fe),
                                                              integral8(r.cum, ra, stride, fa))));
    _mm256_storeu_ps(area + b,
                     _mm512_cvtpd_ps(_mm512_sub_pd(integral8(r.cum_area, re, stride, fe),
                                                   integral8(r.cum_area, ra, stride, fa))));
    const std::size_t lo = r.row(_mm256_cvtsi256_si32(j_lo)) + static_cast<std::size_t>(b);
    const std::size_t hi = r.row(_mm256_cvtsi256_si32(j_hi) + 1) + static_cast<std::size_t>(b);
    const __m256i data = count8(r.cum_data, lo, hi), visible = count8(r.cum_visible, lo, hi),
                  layover = count8(r.cum_layover, lo, hi);
    const __m256i z = _mm256_setzero_si256();
    const __mmask8 no_data = _mm256_cmpeq_epi32_mask(data, z);
    const __mmask8 shadow = static_cast<__mmask8>(_mm256_cmpgt_epi32_mask(data, z) &
                                                  _mm256_cmpeq_epi32_mask(visible, z));
    const __mmask8 laid = _mm256_cmpgt_epi32_mask(layover, z);
    const __m128i m = _mm_or_si128(
        _mm_or_si128(
            _mm_maskz_mov_epi8(no_data, _mm_set1_epi8(static_cast<char>(pixel_flag::kNoData))),
            _mm_maskz_mov_epi8(shadow, _mm_set1_epi8(static_cast<char>(pixel_flag::kShadow)))),
        _mm_maskz_mov_epi8(laid, _mm_set1_epi8(static_cast<char>(pixel_flag::kLayover))));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(mask + b), m);
  }
  return b;
}
#endif

}  // namespace

void emit_line(const EmitRows& r, int k, int begin, int end, float* power, float* area,
               std::uint8_t* mask, bool avx2, bool avx512) {
  int b0 = begin;
#ifdef RIS_HAVE_AVX512_KERNELS
  if (avx512) b0 = emit_line_avx512(r, k, b0, end, power, area, mask);
  if (avx2) b0 = emit_line_avx2(r, k, b0, end, power, area, mask);
#else
  (void)avx2;
  (void)avx512;
#endif
  for (int b = b0; b < end; ++b) emit_pixel(r, k, b, power, area, mask);
}

void push_row_scalar(int n, const std::uint8_t* touch, const float* power, const float* area,
                     const CumRow& prev, const CumRow& next) {
  for (int b = 0; b < n; ++b) {
    const int t = touch[b];
    next.power[b] = prev.power[b] + double(power[b]);
    next.area[b] = prev.area[b] + double(area[b]);
    next.data[b] = prev.data[b] + ((t & slar_touch::kData) != 0);
    next.visible[b] = prev.visible[b] + ((t & slar_touch::kVisible) != 0);
    next.layover[b] = prev.layover[b] + ((t & slar_touch::kLayover) != 0);
  }
}

}  // namespace ris::kernels
