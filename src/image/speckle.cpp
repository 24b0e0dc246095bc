#include "ris/image/speckle.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "ris/util/error.h"

namespace ris {

FadingField::FadingField(std::span<const double> looks_per_bin, FadingLaw law, std::uint64_t seed)
    : looks_(looks_per_bin.begin(), looks_per_bin.end()),
      sqrt_looks_(looks_per_bin.size()),
      law_(law),
      seed_(seed),
      zig_(&ziggurat_tables()) {
  // Per range bin, once: the Gamma sampler's constants and sqrt(N) (the same
  // arithmetic as fading_factor, so the same bytes).
  gamma_.reserve(looks_.size());
  squeeze_in_registers_.resize(looks_.size());
  for (std::size_t b = 0; b < looks_.size(); ++b) {
    RIS_CHECK(looks_[b] > 0.0 && std::isfinite(looks_[b]));
    gamma_.emplace_back(looks_[b]);
    sqrt_looks_[b] = std::sqrt(looks_[b]);
    squeeze_in_registers_[b] = looks_[b] >= 1.0 ? 1 : 0;
  }
}

void FadingField::apply_line(float* row, int line) const {
  const int bins = this->bins();
  const auto line_key = static_cast<std::uint32_t>(line);
  const bool exact = law_ == FadingLaw::exact_gamma;
  // Each pixel draws from its own counter stream (seed, bin, line): its first
  // block comes from the vectorised batch, the rest (rarely needed) from the
  // stream itself.
  constexpr int kChunk = 64;
  alignas(32) std::uint32_t w[4][kChunk];
  for (int b0 = 0; b0 < bins; b0 += kChunk) {
    const int n = std::min(kChunk, bins - b0);
    philox_first_blocks(seed_, static_cast<std::uint32_t>(b0), line_key, CounterRng::kFadingStream,
                        static_cast<std::size_t>(n), {w[0], w[1], w[2], w[3]});
    const ZigguratTables& zig = *zig_;
    for (int i = 0; i < n; ++i) {
      const int bin = b0 + i;
      const float p = row[bin];
      if (!(p > 0.0f) || !std::isfinite(p)) continue;
      const std::size_t b = static_cast<std::size_t>(bin);
      double y = 0.0;
      bool drawn = false;
      // ziggurat_normal's common case: the value's word, the layer's word.
      const auto hz = static_cast<std::int32_t>(w[0][i]);
      const std::uint32_t layer = w[1][i] & 127u;
      const std::uint32_t mag =
          hz < 0 ? 0u - static_cast<std::uint32_t>(hz) : static_cast<std::uint32_t>(hz);
      if (mag < zig.k[layer]) {
        const double x = hz * zig.w[layer];
        if (!exact) {
          y = 1.0 + x / sqrt_looks_[b];
          y = y > kSeedFadingFloor ? y : kSeedFadingFloor;
          drawn = true;
        } else if (squeeze_in_registers_[b]) {
          // GammaSampler's first try: v = (1 + c x)^3, accepted by the squeeze
          // u < 1 - 0.0331 x^4 with u from the third word (boost 1: d v).
          const GammaSampler& g = gamma_[b];
          double v = 1.0 + g.c() * x;
          if (v > 0.0) {
            v = v * v * v;
            const double u = (static_cast<double>(w[2][i]) + 0.5) * 0x1.0p-32;
            const double x2 = x * x;
            if (u < 1.0 - 0.0331 * x2 * x2) {
              y = 1.0 * g.d() * v / looks_[b];
              drawn = true;
            }
          }
        }
      }
      if (!drawn) {
        // Everything else: the pixel's whole draw again, from its stream.
        CounterRng rng(seed_, static_cast<std::uint32_t>(bin), line_key, CounterRng::kFadingStream,
                       {w[0][i], w[1][i], w[2][i], w[3][i]});
        if (exact) {
          y = gamma_[b](rng, zig) / looks_[b];
        } else {
          y = 1.0 + ziggurat_normal(rng, zig) / sqrt_looks_[b];
          y = y > kSeedFadingFloor ? y : kSeedFadingFloor;
        }
      }
      row[bin] = static_cast<float>(static_cast<double>(p) * y);
    }
  }
}

void apply_fading(std::span<float> power_w, int lines, int bins,
                  std::span<const double> looks_per_bin, FadingLaw law, std::uint64_t seed,
                  int first_line) {
  RIS_CHECK(lines >= 0 && bins >= 0);
  RIS_CHECK(power_w.size() == static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins));
  RIS_CHECK(looks_per_bin.size() == static_cast<std::size_t>(bins));
  const FadingField fading(looks_per_bin, law, seed);
  // Lines are independent: any schedule gives the same bytes.
#pragma omp parallel for schedule(static)
  for (int line = 0; line < lines; ++line) {
    fading.apply_line(
        power_w.data() + static_cast<std::size_t>(line) * static_cast<std::size_t>(bins),
        first_line + line);
  }
}

}  // namespace ris
