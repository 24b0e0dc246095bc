// The Philox kernels (ris/util/counter_rng.h): the whole file is the block
// kernel, its AVX-512 intrinsics and their dispatch.
#include "ris/util/counter_rng.h"

#include "ris/kernels/vector_clones.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace ris {

namespace {

// AVX-512 and AVX2 clones beside the SSE2 default, chosen at load time
// (RIS_WIDE_VECTOR_CLONES): 32 x 32 -> 64-bit multiplies eight or four at a
// time (vpmuludq) instead of one; integers only, so every clone gives the
// same bits.

// philox4x32_10 with the rounds over a block of counters, structure of arrays.
RIS_WIDE_VECTOR_CLONES void philox_block_kernel(
    std::uint32_t k0, std::uint32_t k1, std::uint32_t a0, std::uint32_t b, std::uint32_t stream,
    std::size_t n, std::uint32_t* __restrict w0, std::uint32_t* __restrict w1,
    std::uint32_t* __restrict w2, std::uint32_t* __restrict w3) {
  constexpr std::uint64_t kM0 = 0xD2511F53u;
  constexpr std::uint64_t kM1 = 0xCD9E8D57u;
  constexpr std::uint32_t kW0 = 0x9E3779B9u;
  constexpr std::uint32_t kW1 = 0xBB67AE85u;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t c0 = a0 + static_cast<std::uint32_t>(i), c1 = b, c2 = 0u, c3 = stream;
    std::uint32_t key0 = k0, key1 = k1;
    for (int round = 0; round < 10; ++round) {
      const std::uint64_t p0 = kM0 * c0;
      const std::uint64_t p1 = kM1 * c2;
      const std::uint32_t n0 = static_cast<std::uint32_t>(p1 >> 32) ^ c1 ^ key0;
      const std::uint32_t n2 = static_cast<std::uint32_t>(p0 >> 32) ^ c3 ^ key1;
      c1 = static_cast<std::uint32_t>(p1);
      c3 = static_cast<std::uint32_t>(p0);
      c0 = n0;
      c2 = n2;
      key0 += kW0;
      key1 += kW1;
    }
    w0[i] = c0;
    w1[i] = c1;
    w2[i] = c2;
    w3[i] = c3;
  }
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RIS_PHILOX_AVX512 1
// Helpers of philox_avx512 (lambdas would not inherit its target).
// The 32 x 32 -> 64-bit products of sixteen words by m: low and high halves.
__attribute__((target("avx512f"))) inline void mul_hi_lo(__m512i a, __m512i m, __m512i& hi,
                                                         __m512i& lo) {
  // (The zero-masked forms: GCC 12 warns that the plain ones' undefined
  // pass-through source may be used uninitialised.)
  constexpr __mmask8 kAll = 0xff;
  const __m512i even = _mm512_maskz_mul_epu32(kAll, a, m);  // lanes 0, 2, ...
  const __m512i odd = _mm512_maskz_mul_epu32(kAll, _mm512_maskz_srli_epi64(kAll, a, 32), m);
  lo = _mm512_mask_blend_epi32(0xAAAA, even, _mm512_maskz_slli_epi64(kAll, odd, 32));
  hi = _mm512_mask_blend_epi32(0xAAAA, _mm512_maskz_srli_epi64(kAll, even, 32), odd);
}

// philox_block_kernel sixteen counters at a time with AVX-512 intrinsics:
// GCC's own vectorisation of the 64-bit products widens every lane and
// shuffles them back (2.5x slower, measured); here the even and odd words are
// multiplied in place (vpmuludq) and the halves blended. Integers: the same
// bits. Returns the counters done (a multiple of 16).
__attribute__((target("avx512f"))) std::size_t philox_avx512(std::uint32_t k0, std::uint32_t k1,
                                                             std::uint32_t a0, std::uint32_t b,
                                                             std::uint32_t stream, std::size_t n,
                                                             std::uint32_t* w0, std::uint32_t* w1,
                                                             std::uint32_t* w2, std::uint32_t* w3) {
  const __m512i m0 = _mm512_set1_epi64(0xD2511F53u), m1 = _mm512_set1_epi64(0xCD9E8D57u);
  const __m512i lane = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  std::size_t i = 0;
  for (; i + 16 <= n; i += 16) {
    __m512i c0 = _mm512_add_epi32(_mm512_set1_epi32(static_cast<int>(a0 + i)), lane);
    __m512i c1 = _mm512_set1_epi32(static_cast<int>(b)), c2 = _mm512_setzero_si512();
    __m512i c3 = _mm512_set1_epi32(static_cast<int>(stream));
    std::uint32_t key0 = k0, key1 = k1;
    for (int round = 0; round < 10; ++round) {
      __m512i hi0, lo0, hi1, lo1;
      mul_hi_lo(c0, m0, hi0, lo0);
      mul_hi_lo(c2, m1, hi1, lo1);
      c0 = _mm512_ternarylogic_epi32(hi1, c1, _mm512_set1_epi32(static_cast<int>(key0)), 0x96);
      c2 = _mm512_ternarylogic_epi32(hi0, c3, _mm512_set1_epi32(static_cast<int>(key1)), 0x96);
      c1 = lo1;
      c3 = lo0;
      key0 += 0x9E3779B9u;
      key1 += 0xBB67AE85u;
    }
    _mm512_storeu_si512(w0 + i, c0);
    _mm512_storeu_si512(w1 + i, c1);
    _mm512_storeu_si512(w2 + i, c2);
    _mm512_storeu_si512(w3 + i, c3);
  }
  return i;
}
#endif

}  // namespace

void philox_first_blocks(std::uint64_t seed, std::uint32_t a0, std::uint32_t b,
                         std::uint32_t stream, std::size_t n, std::array<std::uint32_t*, 4> words) {
  const auto k0 = static_cast<std::uint32_t>(seed), k1 = static_cast<std::uint32_t>(seed >> 32);
  std::size_t done = 0;
#ifdef RIS_PHILOX_AVX512
  static const bool avx512 = __builtin_cpu_supports("avx512f");
  if (avx512)
    done = philox_avx512(k0, k1, a0, b, stream, n, words[0], words[1], words[2], words[3]);
#endif
  philox_block_kernel(k0, k1, a0 + static_cast<std::uint32_t>(done), b, stream, n - done,
                      words[0] + done, words[1] + done, words[2] + done, words[3] + done);
}

}  // namespace ris
