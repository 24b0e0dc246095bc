#include "ris/util/counter_rng.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ris {
namespace {

// Known-answer vectors of Random123 (tests/kat_vectors, "philox4x32 10" lines):
// counter (4 words), key (2 words) -> output (4 words).
TEST(CounterRng, Philox4x32KnownAnswers) {
  EXPECT_EQ(philox4x32_10({0, 0, 0, 0}, {0, 0}),
            (Philox4x32Block{0x6627e8d5u, 0xe169c58du, 0xbc57ac4cu, 0x9b00dbd8u}));
  EXPECT_EQ(philox4x32_10({0xffffffffu, 0xffffffffu, 0xffffffffu, 0xffffffffu},
                          {0xffffffffu, 0xffffffffu}),
            (Philox4x32Block{0x408f276du, 0x41c83b0eu, 0xa20bc7c6u, 0x6d5451fdu}));
  EXPECT_EQ(philox4x32_10({0x243f6a88u, 0x85a308d3u, 0x13198a2eu, 0x03707344u},
                          {0xa4093822u, 0x299f31d0u}),
            (Philox4x32Block{0xd16cfe09u, 0x94fdccebu, 0x5001e420u, 0x24126ea1u}));
}

TEST(CounterRng, StreamIsKeyedBySeedAndPixel) {
  CounterRng a(42, 3, 7, 0), b(42, 3, 7, 0), c(43, 3, 7, 0), d(42, 4, 7, 0), e(42, 3, 7, 1);
  const std::uint32_t first = a.next_u32();
  EXPECT_EQ(first, b.next_u32());
  EXPECT_NE(first, c.next_u32());
  EXPECT_NE(first, d.next_u32());
  EXPECT_NE(first, e.next_u32());
}

// The batched first blocks are philox4x32_10's bits for every counter (the
// vectorised loop's tail included: n not a multiple of the vector width; a
// key and counters with every bit pattern class), and a CounterRng started
// from one continues as the plain stream does.
TEST(CounterRng, FirstBlocksAreThePhiloxBlocks) {
  for (const std::uint64_t seed : {std::uint64_t{0}, std::uint64_t{42}, ~std::uint64_t{0}}) {
    for (const std::uint32_t a0 : {0u, 1000u, 0xfffffff0u}) {
      constexpr std::size_t kN = 37;
      std::uint32_t w[4][kN];
      philox_first_blocks(seed, a0, 77u, 0x46414400u, kN, {w[0], w[1], w[2], w[3]});
      for (std::size_t i = 0; i < kN; ++i) {
        const auto a = a0 + static_cast<std::uint32_t>(i);  // wraps, as the counter does
        const Philox4x32Block want = philox4x32_10(
            {a, 77u, 0u, 0x46414400u},
            {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)});
        ASSERT_EQ((Philox4x32Block{w[0][i], w[1][i], w[2][i], w[3][i]}), want) << i;
        CounterRng plain(seed, a, 77u, 0x46414400u);
        CounterRng started(seed, a, 77u, 0x46414400u, want);
        for (int k = 0; k < 11; ++k) ASSERT_EQ(started.next_u32(), plain.next_u32()) << k;
      }
    }
  }
}

// Moments of 10^6 draws; tolerances are > 5 standard errors.
TEST(CounterRng, UniformAndNormalMoments) {
  CounterRng rng(7, 0, 0, 0);
  constexpr int kN = 1000000;
  double su = 0, su2 = 0, sz = 0, sz2 = 0, sz4 = 0;
  double umin = 1, umax = 0;
  for (int i = 0; i < kN; ++i) {
    const double u = rng.uniform();
    su += u;
    su2 += u * u;
    umin = std::min(umin, u);
    umax = std::max(umax, u);
    const double z = rng.normal();
    sz += z;
    sz2 += z * z;
    sz4 += z * z * z * z;
  }
  EXPECT_GT(umin, 0.0);
  EXPECT_LT(umax, 1.0);
  EXPECT_NEAR(su / kN, 0.5, 0.0015);              // se 2.9e-4
  EXPECT_NEAR(su2 / kN - 0.25, 1.0 / 12, 0.001);  // variance 1/12
  EXPECT_NEAR(sz / kN, 0.0, 0.005);               // se 1e-3
  EXPECT_NEAR(sz2 / kN, 1.0, 0.01);               // se 1.4e-3
  EXPECT_NEAR(sz4 / kN, 3.0, 0.05);               // kurtosis 3, se 1e-2
}

}  // namespace
}  // namespace ris
