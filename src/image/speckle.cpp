#include "ris/image/speckle.h"

#include <cmath>
#include <cstddef>

#include "ris/util/error.h"

namespace ris {

void apply_fading(std::span<float> power_w, int lines, int bins,
                  std::span<const double> looks_per_bin, FadingLaw law, std::uint64_t seed,
                  int first_line) {
  RIS_CHECK(lines >= 0 && bins >= 0);
  RIS_CHECK(power_w.size() == static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins));
  RIS_CHECK(looks_per_bin.size() == static_cast<std::size_t>(bins));
  for (double n : looks_per_bin) RIS_CHECK(n > 0.0 && std::isfinite(n));
    // Each pixel draws from its own counter stream: any schedule gives the same bytes.
#pragma omp parallel for schedule(static)
  for (int line = 0; line < lines; ++line) {
    float* row = power_w.data() + static_cast<std::size_t>(line) * static_cast<std::size_t>(bins);
    for (int bin = 0; bin < bins; ++bin) {
      const float p = row[bin];
      if (!(p > 0.0f) || !std::isfinite(p)) continue;
      const double y = fading_factor(law, looks_per_bin[static_cast<std::size_t>(bin)], seed,
                                     static_cast<std::uint32_t>(first_line + line),
                                     static_cast<std::uint32_t>(bin));
      row[bin] = static_cast<float>(static_cast<double>(p) * y);
    }
  }
}

}  // namespace ris
