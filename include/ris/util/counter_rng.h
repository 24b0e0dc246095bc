// Counter-based random numbers keyed by (seed, pixel), so that a result never
// depends on thread count, tiling or run order (DESIGN.md principle 7).
//
// The generator is Philox4x32-10 of J. K. Salmon, M. A. Moraes, R. O. Dror and
// D. E. Shaw, "Parallel random numbers: as easy as 1, 2, 3", SC'11 (2011),
// written from the paper's description: a 128-bit counter is encrypted under
// a 64-bit key by 10 rounds of two 32x32->64 bit multiplications
// (M0 = 0xD2511F53, M1 = 0xCD9E8D57) with a Weyl key schedule
// (W0 = 0x9E3779B9, W1 = 0xBB67AE85). Checked against the known-answer
// vectors of the authors' Random123 library (tests/kat_vectors) in
// counter_rng_test.cpp, and bit for bit against Random123 1.14 itself
// (Debian's librandom123-dev) on a million blocks and on the batched first
// blocks in counter_rng_random123_test.cpp. Kept in ris (30 lines) rather
// than calling Random123's scalar generator because the speckle needs the
// many-counters-at-once form below, which the vectorised kernel in
// src/kernels/util/counter_rng.cpp computes and this function is the
// reference for.
//
// CounterRng is a stream for one pixel: key = seed, counter = (a, b, draw,
// stream), so each (a, b) pixel, e.g. (bin, line), gets its own 2^32 blocks of
// four 32-bit words, and `stream` separates unrelated uses of the same pixel.
//
// Example:
//   ris::CounterRng rng(seed, bin, line, ris::CounterRng::kFadingStream);
//   double u = rng.uniform();   // in (0, 1)
//   double z = rng.normal();    // N(0, 1)
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace ris {

using Philox4x32Block = std::array<std::uint32_t, 4>;
using Philox4x32Key = std::array<std::uint32_t, 2>;

// One Philox4x32-10 block: encrypts `counter` under `key`.
inline Philox4x32Block philox4x32_10(Philox4x32Block ctr, Philox4x32Key key) {
  constexpr std::uint64_t kM0 = 0xD2511F53u;
  constexpr std::uint64_t kM1 = 0xCD9E8D57u;
  constexpr std::uint32_t kW0 = 0x9E3779B9u;
  constexpr std::uint32_t kW1 = 0xBB67AE85u;
  for (int round = 0; round < 10; ++round) {
    if (round > 0) {
      key[0] += kW0;
      key[1] += kW1;
    }
    const std::uint64_t p0 = kM0 * ctr[0];
    const std::uint64_t p1 = kM1 * ctr[2];
    ctr = {static_cast<std::uint32_t>(p1 >> 32) ^ ctr[1] ^ key[0], static_cast<std::uint32_t>(p1),
           static_cast<std::uint32_t>(p0 >> 32) ^ ctr[3] ^ key[1], static_cast<std::uint32_t>(p0)};
  }
  return ctr;
}

// The first block of the streams (a0 + i, b, stream) of CounterRng, i in
// [0, n): word k of stream i in words[k][i]. The same bits as philox4x32_10,
// computed for many counters at once so that the rounds vectorise (the
// speckle draws one stream per pixel of a line: a0 = the first bin, b = the
// line). Integer arithmetic only, so an AVX2 clone gives the same bits.
void philox_first_blocks(std::uint64_t seed, std::uint32_t a0, std::uint32_t b,
                         std::uint32_t stream, std::size_t n, std::array<std::uint32_t*, 4> words);

class CounterRng {
 public:
  static constexpr std::uint32_t kFadingStream = 0x46414400u;  // "FAD\0"

  CounterRng(std::uint64_t seed, std::uint32_t a, std::uint32_t b, std::uint32_t stream)
      : key_{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)},
        ctr_{a, b, 0u, stream} {}

  // The same stream with its first block already computed (philox4x32_10 of
  // the counter (a, b, 0, stream) under the seed, e.g. by
  // philox_first_blocks for many pixels at once): the same numbers as the
  // constructor above gives.
  CounterRng(std::uint64_t seed, std::uint32_t a, std::uint32_t b, std::uint32_t stream,
             const Philox4x32Block& first_block)
      : key_{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)},
        ctr_{a, b, 1u, stream},
        block_(first_block),
        used_(0) {}

  std::uint32_t next_u32() {
    if (used_ == 4) {
      block_ = philox4x32_10(ctr_, key_);
      ++ctr_[2];
      used_ = 0;
    }
    return block_[used_++];
  }

  // Uniform in the open interval (0, 1) with 53 random bits.
  double uniform() {
    const std::uint64_t hi = next_u32() >> 5;  // 27 bits
    const std::uint64_t lo = next_u32() >> 6;  // 26 bits
    return (static_cast<double>((hi << 26) | lo) + 0.5) * 0x1.0p-53;
  }

  // Uniform in (0, 1) from one 32-bit word (2^-32 resolution): for
  // acceptance tests, where 53 bits buy nothing.
  double uniform32() { return (static_cast<double>(next_u32()) + 0.5) * 0x1.0p-32; }

  // Standard normal by the Box-Muller transform (Box and Muller, Ann. Math.
  // Statist. 29, 1958), both variates of a pair used in turn.
  double normal() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    const double r = std::sqrt(-2.0 * std::log(uniform()));
    const double t = 2.0 * 3.14159265358979323846 * uniform();
    spare_ = r * std::sin(t);
    has_spare_ = true;
    return r * std::cos(t);
  }

 private:
  Philox4x32Key key_;
  Philox4x32Block ctr_;
  Philox4x32Block block_{};
  int used_ = 4;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

}  // namespace ris
