// The greytone quantiser's kernels (kernels/image/greytone_kernels.h),
// moved from image/greytone.cpp unchanged.
#include "kernels/image/greytone_kernels.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstring>

#include "ris/kernels/vector_clones.h"

namespace ris::kernels {

namespace {

// An AVX2 clone beside the SSE2 default (GCC function multiversioning, as
// kernels/geometry/line_scan.cpp): the table lookups as gathers. Integer and
// compare operations only, so both clones give the same bytes.

// quantise_line's loop for a fixed number of threshold steps (1 for any
// ordinary film: the compiler unrolls it).
template <unsigned Steps>
void quantise_kernel(const float* __restrict power_w, const std::uint8_t* __restrict mask,
                     std::uint8_t mask_bits, std::size_t n, std::uint8_t* __restrict out,
                     std::uint8_t no_data_greytone, const std::uint8_t* __restrict bucket,
                     const float* __restrict threshold, unsigned steps) {
  for (std::size_t i = 0; i < n; ++i) {
    const float p = power_w[i];
    std::uint32_t bits = 0;
    std::memcpy(&bits, &p, sizeof bits);
    // Negative powers and -0 read bucket 0 (greytone 0, below every
    // threshold), NaN and +inf the last bucket (NaN is masked below).
    const std::uint32_t b = std::min(bits >> 16, 0x7f80u) & ~(0u - (bits >> 31));
    unsigned g = bucket[b];
    for (unsigned s = 0; s < (Steps > 0 ? Steps : steps); ++s) g += p >= threshold[g + 1] ? 1u : 0u;
    const bool masked = std::isnan(p) || (mask != nullptr && (mask[i] & mask_bits) != 0);
    out[i] = masked ? no_data_greytone : static_cast<std::uint8_t>(g);
  }
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
// quantise_kernel<1> eight pixels at a time with one lookup of bucket_step
// per pixel (the bucket's greytone and its threshold's low bits: a second
// lookup of the threshold cost ~40% of the kernel on this EPYC), the tail by
// the scalar kernel. The eight lookups are scalar loads inserted into the
// vector: the AVX2 gather instruction they replace was ~30% slower on this
// EPYC (BM_GreytoneLine), as for the ground-range resampling. Integer operations only: the same
// bytes (a power below zero has negative bits, below every threshold, as in the float compare).
__attribute__((target("avx2"))) void quantise_one_step_avx2(
    const float* __restrict power_w, const std::uint8_t* __restrict mask, std::uint8_t mask_bits,
    std::size_t n, std::uint8_t* __restrict out, std::uint8_t no_data_greytone,
    const std::uint32_t* __restrict bucket_step, const std::uint8_t* __restrict bucket,
    const float* __restrict threshold) {
  const __m256i last_bucket = _mm256_set1_epi32(0x7f80);
  const __m256i step_bits = _mm256_set1_epi32(0x1ffff);
  const __m256i one = _mm256_set1_epi32(1);
  const __m256i no_data = _mm256_set1_epi32(no_data_greytone);
  const __m256i bits_wanted = _mm256_set1_epi32(mask_bits);
  const __m256i zero = _mm256_setzero_si256();
  std::size_t i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m256 p = _mm256_loadu_ps(power_w + i);
    const __m256i bits = _mm256_castps_si256(p);
    // min(bits >> 16, 0x7f80), 0 for a set sign bit (as the scalar kernel).
    __m256i b = _mm256_min_epu32(_mm256_srli_epi32(bits, 16), last_bucket);
    b = _mm256_andnot_si256(_mm256_srai_epi32(bits, 31), b);
    alignas(32) std::uint32_t idx[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(idx), b);
    const __m128i e_lo = _mm_insert_epi32(
        _mm_insert_epi32(_mm_insert_epi32(_mm_cvtsi32_si128(static_cast<int>(bucket_step[idx[0]])),
                                          static_cast<int>(bucket_step[idx[1]]), 1),
                         static_cast<int>(bucket_step[idx[2]]), 2),
        static_cast<int>(bucket_step[idx[3]]), 3);
    const __m128i e_hi = _mm_insert_epi32(
        _mm_insert_epi32(_mm_insert_epi32(_mm_cvtsi32_si128(static_cast<int>(bucket_step[idx[4]])),
                                          static_cast<int>(bucket_step[idx[5]]), 1),
                         static_cast<int>(bucket_step[idx[6]]), 2),
        static_cast<int>(bucket_step[idx[7]]), 3);
    const __m256i e = _mm256_inserti128_si256(_mm256_castsi128_si256(e_lo), e_hi, 1);
    const __m256i t = _mm256_add_epi32(_mm256_slli_epi32(b, 16), _mm256_and_si256(e, step_bits));
    // g + 1, less one where the threshold is above the power's bits.
    __m256i g = _mm256_add_epi32(_mm256_add_epi32(_mm256_srli_epi32(e, 17), one),
                                 _mm256_cmpgt_epi32(t, bits));
    __m256i masked = _mm256_castps_si256(_mm256_cmp_ps(p, p, _CMP_UNORD_Q));
    if (mask != nullptr) {
      std::uint64_t m8 = 0;
      std::memcpy(&m8, mask + i, sizeof m8);
      const __m256i m = _mm256_and_si256(
          _mm256_cvtepu8_epi32(_mm_cvtsi64_si128(static_cast<long long>(m8))), bits_wanted);
      masked = _mm256_or_si256(
          masked, _mm256_xor_si256(_mm256_cmpeq_epi32(m, zero), _mm256_set1_epi32(-1)));
    }
    g = _mm256_blendv_epi8(g, no_data, masked);
    const __m128i g16 = _mm_packus_epi32(_mm256_castsi256_si128(g), _mm256_extracti128_si256(g, 1));
    const __m128i g8 = _mm_packus_epi16(g16, g16);
    _mm_storel_epi64(reinterpret_cast<__m128i*>(out + i), g8);
  }
  quantise_kernel<1>(power_w + i, mask ? mask + i : nullptr, mask_bits, n - i, out + i,
                     no_data_greytone, bucket, threshold, 1);
}
#endif

RIS_VECTOR_CLONES void quantise_one_step_clones(
    const float* __restrict power_w, const std::uint8_t* __restrict mask, std::uint8_t mask_bits,
    std::size_t n, std::uint8_t* __restrict out, std::uint8_t no_data_greytone,
    const std::uint8_t* __restrict bucket, const float* __restrict threshold) {
  quantise_kernel<1>(power_w, mask, mask_bits, n, out, no_data_greytone, bucket, threshold, 1);
}

}  // namespace

void quantise_one_step(bool avx2, const float* power_w, const std::uint8_t* mask,
                       std::uint8_t mask_bits, std::size_t n, std::uint8_t* out,
                       std::uint8_t no_data_greytone, const std::uint32_t* bucket_step,
                       const std::uint8_t* bucket, const float* threshold) {
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
  if (avx2) {
    quantise_one_step_avx2(power_w, mask, mask_bits, n, out, no_data_greytone, bucket_step, bucket,
                           threshold);
    return;
  }
#else
  (void)avx2;
  (void)bucket_step;
#endif
  quantise_one_step_clones(power_w, mask, mask_bits, n, out, no_data_greytone, bucket, threshold);
}

void quantise_one_step_scalar(const float* power_w, const std::uint8_t* mask,
                              std::uint8_t mask_bits, std::size_t n, std::uint8_t* out,
                              std::uint8_t no_data_greytone, const std::uint8_t* bucket,
                              const float* threshold) {
  quantise_kernel<1>(power_w, mask, mask_bits, n, out, no_data_greytone, bucket, threshold, 1);
}

void quantise_steps(const float* power_w, const std::uint8_t* mask, std::uint8_t mask_bits,
                    std::size_t n, std::uint8_t* out, std::uint8_t no_data_greytone,
                    const std::uint8_t* bucket, const float* threshold, unsigned steps) {
  quantise_kernel<0>(power_w, mask, mask_bits, n, out, no_data_greytone, bucket, threshold, steps);
}

}  // namespace ris::kernels
