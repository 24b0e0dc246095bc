#include "ris/util/counter_rng.h"

namespace ris {

namespace {

// AVX-512 and AVX2 clones beside the SSE2 default, chosen at load time (GCC
// function multiversioning, as ris/geometry/line_scan.cpp): 32 x 32 -> 64-bit
// multiplies eight or four at a time (vpmuludq) instead of one; integers
// only, so every clone gives the same bits.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RIS_PHILOX_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define RIS_PHILOX_CLONES
#endif

// philox4x32_10 with the rounds over a block of counters, structure of arrays.
RIS_PHILOX_CLONES void philox_block_kernel(std::uint32_t k0, std::uint32_t k1, std::uint32_t a0,
                                           std::uint32_t b, std::uint32_t stream, std::size_t n,
                                           std::uint32_t* __restrict w0,
                                           std::uint32_t* __restrict w1,
                                           std::uint32_t* __restrict w2,
                                           std::uint32_t* __restrict w3) {
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

}  // namespace

void philox_first_blocks(std::uint64_t seed, std::uint32_t a0, std::uint32_t b,
                         std::uint32_t stream, std::size_t n, std::array<std::uint32_t*, 4> words) {
  philox_block_kernel(static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32), a0,
                      b, stream, n, words[0], words[1], words[2], words[3]);
}

}  // namespace ris
