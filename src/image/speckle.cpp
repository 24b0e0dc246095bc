#include "ris/image/speckle.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "kernels/image/speckle_kernels.h"
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
    squeeze_c_.push_back(squeeze_in_registers_[b] ? gamma_[b].c()
                                                  : std::numeric_limits<double>::quiet_NaN());
    squeeze_d_.push_back(gamma_[b].d());
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
  // The AVX2 kernels (kernels/image/speckle_kernels.h) where the CPU has them.
  const bool avx2 = kernels::fade_quads_available();
  for (int b0 = 0; b0 < bins; b0 += kChunk) {
    const int n = std::min(kChunk, bins - b0);
    // A chunk with nothing to fade (no data or no power: an oblique track's
    // image is about half such pixels, outside the rotated scene) draws
    // nothing; every pixel has its own stream, so the others' bytes are the
    // same.
    if (!kernels::any_to_fade(avx2, row + b0, n)) continue;
    philox_first_blocks(seed_, static_cast<std::uint32_t>(b0), line_key, CounterRng::kFadingStream,
                        static_cast<std::size_t>(n), {w[0], w[1], w[2], w[3]});
    const ZigguratTables& zig = *zig_;
    // Which pixels the scalar path draws: all, or those the vector kernel
    // left (bit i: pixel b0 + i).
    std::uint64_t todo = n == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
    if (avx2) {
      const std::size_t at = static_cast<std::size_t>(b0);
      todo =
          kernels::fade_quads(row + b0, n, w[0], w[1], w[2], zig, exact, squeeze_c_.data() + at,
                              squeeze_d_.data() + at, looks_.data() + at, sqrt_looks_.data() + at);
    }
    for (; todo != 0; todo &= todo - 1) {
      const int i = std::countr_zero(todo);
      const int bin = b0 + i;
      const float p = row[bin];
      if (!(p > 0.0f) || !std::isfinite(p)) continue;
      const std::size_t b = static_cast<std::size_t>(bin);
      double y = 0.0;
      bool drawn = false;
      // The words of the pixel's stream its first try used, when it ended
      // without a value (rejected, or v <= 0) and N >= 1: the sampler's next
      // try starts after them, exactly as in its own loop (a v <= 0 redraws
      // the normal from the next word, as a new try does; nothing else is
      // drawn in between and N >= 1 draws no boost). 0: draw the pixel anew.
      int words_used = 0;
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
          // GammaSampler's first try: v = (1 + c x)^3 and u from the third
          // word, accepted by its squeeze or its logarithmic test (boost 1:
          // d v).
          const GammaSampler& g = gamma_[b];
          double v = 1.0 + g.c() * x;
          words_used = 2;
          if (v > 0.0) {
            v = v * v * v;
            const double u = (static_cast<double>(w[2][i]) + 0.5) * 0x1.0p-32;
            const double x2 = x * x;
            words_used = 3;
            // The squeeze, then (as GammaSampler, with the same values) the
            // logarithmic test before any further draw.
            if (u < 1.0 - 0.0331 * x2 * x2 ||
                std::log(u) < 0.5 * x2 + g.d() * (1.0 - v + std::log(v))) {
              y = 1.0 * g.d() * v / looks_[b];
              drawn = true;
            }
          }
        }
      }
      if (!drawn) {
        // Everything else: the draw goes on from the pixel's stream (after
        // the first try's words) or starts again there.
        CounterRng rng(seed_, static_cast<std::uint32_t>(bin), line_key, CounterRng::kFadingStream,
                       {w[0][i], w[1][i], w[2][i], w[3][i]});
        for (int k = 0; k < words_used; ++k) rng.next_u32();
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
