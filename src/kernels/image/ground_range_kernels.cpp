// The ground-range resampler's kernels (kernels/image/ground_range_kernels.h),
// moved from image/ground_range.cpp unchanged.
#include "kernels/image/ground_range_kernels.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace ris::kernels {

namespace {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
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

void resample_columns(bool avx2, const float* slant, int bins, const std::int32_t* k0,
                      const std::int32_t* k1, const double* w, std::size_t begin, std::size_t end,
                      float* out) {
  std::size_t j = begin;
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
  if (avx2) {
    resample_avx2(slant, bins, k0, k1, w, j, end, out);
    j = end;
  }
#else
  (void)avx2;
  (void)bins;
#endif
  for (; j < end; ++j) {
    const float a = slant[k0[j]], b = slant[k1[j]];
    out[j] = static_cast<float>(a + w[j] * (double(b) - double(a)));
  }
}

void nearest_columns(bool avx2, const std::uint8_t* slant, int bins, const std::int32_t* nearest,
                     std::size_t begin, std::size_t end, std::uint8_t* out) {
  std::size_t j = begin;
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
  if (avx2) {
    nearest_avx2(slant, bins, nearest, j, end, out);
    j = end;
  }
#else
  (void)avx2;
  (void)bins;
#endif
  for (; j < end; ++j) out[j] = slant[nearest[j]];
}

}  // namespace ris::kernels
