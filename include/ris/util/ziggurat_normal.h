// Standard normal variates by the ziggurat method (G. Marsaglia and W. W.
// Tsang, "The Ziggurat Method for Generating Random Variables", J. Stat.
// Software 5(8), 2000; 128 layers), drawn from a CounterRng stream. Exact
// (a rejection method, not an approximation); ~98.8% of draws take two
// 32-bit words, a multiply and a compare, against Box-Muller's log, sqrt and
// sincos. The layer index comes from a word of its own, not from the low bits
// of the value (J. A. Doornik, "An Improved Ziggurat Method to Generate
// Normal Random Samples", 2005, on the original's correlation between them).
//
// Used by the speckle (ris/image/speckle.h), where one normal per pixel made
// Box-Muller the render's largest cost. CounterRng::normal() (Box-Muller)
// stays as it is, so the fractal terrain does not change.
//
// Example:
//   const ris::ZigguratTables& zig = ris::ziggurat_tables();  // once
//   ris::CounterRng rng(seed, bin, line, stream);
//   double z = ris::ziggurat_normal(rng, zig);
#pragma once

#include <cmath>
#include <cstdint>

#include "ris/util/counter_rng.h"

namespace ris {

struct ZigguratTables {
  static constexpr double kR = 3.442619855899;  // start of the tail
  std::uint32_t k[128];                         // |hz| < k[i]: inside layer i's rectangle
  double w[128];                                // x = hz w[i]
  double f[128];                                // exp(-x_i^2 / 2) at the layers' edges
};

// Built once (thread-safe), then read-only.
const ZigguratTables& ziggurat_tables();

inline double ziggurat_normal(CounterRng& rng, const ZigguratTables& t) {
  for (;;) {
    const auto hz = static_cast<std::int32_t>(rng.next_u32());
    const std::uint32_t i = rng.next_u32() & 127u;
    const std::uint32_t mag =
        hz < 0 ? 0u - static_cast<std::uint32_t>(hz) : static_cast<std::uint32_t>(hz);
    const double x = hz * t.w[i];
    if (mag < t.k[i]) return x;  // the common case
    if (i == 0) {
      // The tail beyond R (Marsaglia's method for the normal tail).
      double xt = 0.0, y = 0.0;
      do {
        xt = -std::log(rng.uniform32()) / ZigguratTables::kR;
        y = -std::log(rng.uniform32());
      } while (y + y < xt * xt);
      return hz > 0 ? ZigguratTables::kR + xt : -ZigguratTables::kR - xt;
    }
    // The wedge between the rectangle and the density.
    if (t.f[i] + rng.uniform32() * (t.f[i - 1] - t.f[i]) < std::exp(-0.5 * x * x)) return x;
  }
}

}  // namespace ris
