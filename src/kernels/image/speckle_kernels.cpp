// The fading kernels (kernels/image/speckle_kernels.h), moved from
// image/speckle.cpp unchanged.
#include "kernels/image/speckle_kernels.h"

#include <cmath>

#include "kernels/simd/cpu.h"
#include "ris/image/speckle.h"

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#include <immintrin.h>
#define RIS_SPECKLE_AVX2 1
#endif

namespace ris::kernels {

namespace {

#ifdef RIS_SPECKLE_AVX2
// FadingField::apply_line's draw in registers, four pixels at a time (AVX2:
// the ziggurat's table entries of the four layers; the arithmetic in double with separate
// multiplies and adds in the scalar code's order, so the same bytes). Writes
// the pixels it decides and returns a bit per pixel (of n <= 64) that the
// scalar path must still draw: a draw needing more words, and the last n % 4.
// No-data and non-positive pixels are left alone, as the scalar path does.
__attribute__((target("avx2"))) std::uint64_t fade_quads_avx2(
    float* row, int n, const std::uint32_t* w0, const std::uint32_t* w1, const std::uint32_t* w2,
    const ZigguratTables& zig, bool exact, const double* c, const double* d, const double* looks,
    const double* sqrt_looks) {
  const __m256d one = _mm256_set1_pd(1.0);
  const __m128i sign = _mm_set1_epi32(static_cast<int>(0x80000000u));
  std::uint64_t pending = 0;
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m128 p = _mm_loadu_ps(row + i);
    const __m128 valid = _mm_and_ps(_mm_cmp_ps(p, _mm_setzero_ps(), _CMP_GT_OQ),
                                    _mm_cmp_ps(p, _mm_set1_ps(HUGE_VALF), _CMP_LT_OQ));
    // ziggurat_normal's common case.
    const __m128i hz = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w0 + i));
    const __m128i layer = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(w1 + i)),
                                        _mm_set1_epi32(127));
    // The layers' table entries by scalar loads (AVX2 gathers were slower on
    // this EPYC, BM_Fading).
    alignas(16) std::uint32_t l[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(l), layer);
    const __m128i k = _mm_setr_epi32(static_cast<int>(zig.k[l[0]]), static_cast<int>(zig.k[l[1]]),
                                     static_cast<int>(zig.k[l[2]]), static_cast<int>(zig.k[l[3]]));
    const __m128i in_rect =  // |hz| < k, unsigned
        _mm_cmpgt_epi32(_mm_xor_si128(k, sign), _mm_xor_si128(_mm_abs_epi32(hz), sign));
    const __m256d x = _mm256_mul_pd(
        _mm256_cvtepi32_pd(hz), _mm256_setr_pd(zig.w[l[0]], zig.w[l[1]], zig.w[l[2]], zig.w[l[3]]));
    __m256d y, fast = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(in_rect));
    if (exact) {
      // GammaSampler's first try and its squeeze (see apply_line).
      const __m256d v = _mm256_add_pd(one, _mm256_mul_pd(_mm256_loadu_pd(c + i), x));
      const __m256d v3 = _mm256_mul_pd(_mm256_mul_pd(v, v), v);
      const __m128i u32 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w2 + i));
      const __m256d u_int = _mm256_add_pd(_mm256_cvtepi32_pd(_mm_xor_si128(u32, sign)),
                                          _mm256_set1_pd(2147483648.0));  // the word, exactly
      const __m256d u =
          _mm256_mul_pd(_mm256_add_pd(u_int, _mm256_set1_pd(0.5)), _mm256_set1_pd(0x1.0p-32));
      const __m256d x2 = _mm256_mul_pd(x, x);
      const __m256d squeeze =
          _mm256_sub_pd(one, _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(0.0331), x2), x2));
      fast = _mm256_and_pd(fast, _mm256_cmp_pd(v, _mm256_setzero_pd(), _CMP_GT_OQ));
      fast = _mm256_and_pd(fast, _mm256_cmp_pd(u, squeeze, _CMP_LT_OQ));
      y = _mm256_div_pd(_mm256_mul_pd(_mm256_mul_pd(one, _mm256_loadu_pd(d + i)), v3),
                        _mm256_loadu_pd(looks + i));
    } else {
      const __m256d floor = _mm256_set1_pd(kSeedFadingFloor);
      y = _mm256_add_pd(one, _mm256_div_pd(x, _mm256_loadu_pd(sqrt_looks + i)));
      y = _mm256_blendv_pd(floor, y, _mm256_cmp_pd(y, floor, _CMP_GT_OQ));
    }
    const __m128 faded = _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_cvtps_pd(p), y));
    // The four 64-bit lane masks as 32-bit ones (each lane's low half).
    const __m128 fast4 =
        _mm_shuffle_ps(_mm256_castps256_ps128(_mm256_castpd_ps(fast)),
                       _mm256_extractf128_ps(_mm256_castpd_ps(fast), 1), _MM_SHUFFLE(2, 0, 2, 0));
    _mm_storeu_ps(row + i, _mm_blendv_ps(p, faded, _mm_and_ps(valid, fast4)));
    const int slow = _mm_movemask_ps(_mm_andnot_ps(fast4, valid));
    pending |= static_cast<std::uint64_t>(slow) << i;
  }
  for (; i < n; ++i) pending |= std::uint64_t{1} << i;
  return pending;
}
#endif

// Whether any of the n pixels has a positive, finite power (the pixels
// apply_line fades; it leaves the others as they are).
bool any_to_fade_scalar(const float* row, int n) {
  bool any = false;
  for (int i = 0; i < n; ++i) any |= (row[i] > 0.0f) & (row[i] < HUGE_VALF);
  return any;
}

#ifdef RIS_SPECKLE_AVX2
// any_to_fade eight pixels at a time, stopping at the first block with one
// (GCC left the loop above scalar: 13% of apply_line's samples).
__attribute__((target("avx2"))) bool any_to_fade_avx2(const float* row, int n) {
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m256 p = _mm256_loadu_ps(row + i);
    const __m256 fade = _mm256_and_ps(_mm256_cmp_ps(p, _mm256_setzero_ps(), _CMP_GT_OQ),
                                      _mm256_cmp_ps(p, _mm256_set1_ps(HUGE_VALF), _CMP_LT_OQ));
    if (_mm256_movemask_ps(fade) != 0) return true;
  }
  return any_to_fade_scalar(row + i, n - i);
}
#endif

}  // namespace

bool fade_quads_available() {
#ifdef RIS_SPECKLE_AVX2
  return cpu_has_avx2();
#else
  return false;
#endif
}

std::uint64_t fade_quads(float* row, int n, const std::uint32_t* w0, const std::uint32_t* w1,
                         const std::uint32_t* w2, const ZigguratTables& zig, bool exact,
                         const double* c, const double* d, const double* looks,
                         const double* sqrt_looks) {
#ifdef RIS_SPECKLE_AVX2
  return fade_quads_avx2(row, n, w0, w1, w2, zig, exact, c, d, looks, sqrt_looks);
#else
  (void)row, (void)w0, (void)w1, (void)w2, (void)zig, (void)exact, (void)c, (void)d, (void)looks,
      (void)sqrt_looks;
  return n == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
#endif
}

bool any_to_fade(bool avx2, const float* row, int n) {
#ifdef RIS_SPECKLE_AVX2
  if (avx2) return any_to_fade_avx2(row, n);
#else
  (void)avx2;
#endif
  return any_to_fade_scalar(row, n);
}

}  // namespace ris::kernels
