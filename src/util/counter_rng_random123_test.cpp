// ris's Philox4x32-10 (ris/util/counter_rng.h) against the authors' own
// implementation, Random123 1.14 as Debian packages it (librandom123-dev,
// header-only): the same 128 output bits for a million counter/key pairs
// drawn from every bit-pattern class, and for the batched first blocks the
// speckle uses. The known-answer vectors in counter_rng_test.cpp pin three
// points; this pins the function.
#include <Random123/philox.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <random>
#include <vector>

#include "ris/util/counter_rng.h"

namespace ris {
namespace {

Philox4x32Block reference_philox(const Philox4x32Block& c, const Philox4x32Key& k) {
  r123::Philox4x32_R<10> gen;
  const r123::Philox4x32_R<10>::ctr_type ctr = {{c[0], c[1], c[2], c[3]}};
  const r123::Philox4x32_R<10>::key_type key = {{k[0], k[1]}};
  const auto out = gen(ctr, key);
  return {out[0], out[1], out[2], out[3]};
}

// Words of every class: uniform, all-zero, all-one, single bits, near 2^32.
std::uint32_t word(std::mt19937_64& g) {
  switch (g() % 5) {
    case 0:
      return 0u;
    case 1:
      return 0xffffffffu;
    case 2:
      return 1u << (g() % 32);
    case 3:
      return 0xffffffffu - static_cast<std::uint32_t>(g() % 4);
    default:
      return static_cast<std::uint32_t>(g());
  }
}

TEST(CounterRngRandom123, SameBitsAsTheReferenceForAMillionBlocks) {
  std::mt19937_64 g(20261126);
  for (int i = 0; i < 1000000; ++i) {
    const Philox4x32Block c{word(g), word(g), word(g), word(g)};
    const Philox4x32Key k{word(g), word(g)};
    const Philox4x32Block want = reference_philox(c, k);
    const Philox4x32Block got = philox4x32_10(c, k);
    ASSERT_EQ(got, want) << "block " << i;
  }
}

TEST(CounterRngRandom123, BatchedFirstBlocksAreTheReferenceBlocks) {
  constexpr std::size_t kN = 1037;  // not a multiple of any vector width
  std::vector<std::uint32_t> w[4];
  for (auto& v : w) v.resize(kN);
  for (const std::uint64_t seed : {0ull, 1ull, 0xfedcba9876543210ull}) {
    for (const std::uint32_t a0 : {0u, 0xfffffc00u}) {
      philox_first_blocks(seed, a0, 5u, CounterRng::kFadingStream, kN,
                          {w[0].data(), w[1].data(), w[2].data(), w[3].data()});
      const Philox4x32Key key{static_cast<std::uint32_t>(seed),
                              static_cast<std::uint32_t>(seed >> 32)};
      for (std::size_t i = 0; i < kN; ++i) {
        const std::uint32_t a = a0 + static_cast<std::uint32_t>(i);  // wraps as the counter does
        const Philox4x32Block want = reference_philox({a, 5u, 0u, CounterRng::kFadingStream}, key);
        ASSERT_EQ((Philox4x32Block{w[0][i], w[1][i], w[2][i], w[3][i]}), want)
            << "seed " << seed << " a " << a;
      }
    }
  }
}

}  // namespace
}  // namespace ris
