#include "ris/image/speckle.h"

#include <cmath>
#include <cstddef>
#include <vector>

#include "ris/util/error.h"

namespace ris {

void apply_fading(std::span<float> power_w, int lines, int bins,
                  std::span<const double> looks_per_bin, FadingLaw law, std::uint64_t seed,
                  int first_line) {
  RIS_CHECK(lines >= 0 && bins >= 0);
  RIS_CHECK(power_w.size() == static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins));
  RIS_CHECK(looks_per_bin.size() == static_cast<std::size_t>(bins));
  for (double n : looks_per_bin) RIS_CHECK(n > 0.0 && std::isfinite(n));
  // Per range bin, once: the Gamma sampler's constants and sqrt(N) (the same
  // arithmetic as fading_factor, so the same bytes).
  std::vector<GammaSampler> gamma;
  std::vector<double> sqrt_looks(looks_per_bin.size());
  gamma.reserve(looks_per_bin.size());
  for (std::size_t b = 0; b < looks_per_bin.size(); ++b) {
    gamma.emplace_back(looks_per_bin[b]);
    sqrt_looks[b] = std::sqrt(looks_per_bin[b]);
  }
  const ZigguratTables& zig = ziggurat_tables();
  const bool exact = law == FadingLaw::exact_gamma;
  // Each pixel draws from its own counter stream: any schedule gives the same bytes.
#pragma omp parallel for schedule(static)
  for (int line = 0; line < lines; ++line) {
    float* row = power_w.data() + static_cast<std::size_t>(line) * static_cast<std::size_t>(bins);
    const auto line_key = static_cast<std::uint32_t>(first_line + line);
    for (int bin = 0; bin < bins; ++bin) {
      const float p = row[bin];
      if (!(p > 0.0f) || !std::isfinite(p)) continue;
      const std::size_t b = static_cast<std::size_t>(bin);
      CounterRng rng(seed, static_cast<std::uint32_t>(bin), line_key, CounterRng::kFadingStream);
      double y = 0.0;
      if (exact) {
        y = gamma[b](rng, zig) / looks_per_bin[b];
      } else {
        y = 1.0 + ziggurat_normal(rng, zig) / sqrt_looks[b];
        y = y > kSeedFadingFloor ? y : kSeedFadingFloor;
      }
      row[bin] = static_cast<float>(static_cast<double>(p) * y);
    }
  }
}

}  // namespace ris
