#include "ris/backscatter/sigma0_lut.h"

#include <fmt/format.h>

#include <cmath>

#include "ris/scene/scene.h"
#include "ris/util/error.h"

namespace ris {

Sigma0Lut Sigma0Lut::build(const Sigma0Source& source, const RadarBand& band,
                           std::span<const std::uint16_t> categories,
                           const std::string& source_name) {
  Sigma0Lut lut;
  std::uint16_t max_category = 0;
  for (std::uint16_t c : categories) {
    if (c != kNoDataCategory) max_category = std::max(max_category, c);
  }
  lut.offset_.assign(static_cast<size_t>(max_category) + 1, -1);
  for (std::uint16_t c : categories) {
    if (c == kNoDataCategory || lut.offset_[c] >= 0) continue;
    if (!source.has_category(c)) {
      throw InputError(source_name, "",
                       fmt::format("no backscatter for category {} (the scene uses it; add it to "
                                   "the backscatter file)",
                                   c));
    }
    lut.offset_[c] = static_cast<std::int64_t>(lut.table_.size());
    for (int i = 0; i <= kSteps; ++i) {
      const double theta = std::min(i * kStepRad, kPi / 2.0);
      const double s0 = source.sigma0(c, theta, band);
      if (!std::isfinite(s0) || s0 < 0.0) {
        throw InputError(source_name, "",
                         fmt::format("category {} gives sigma0 = {} at {:.2f} deg; expected a "
                                     "finite value >= 0",
                                     c, s0, rad_to_deg(theta)));
      }
      lut.table_.push_back(static_cast<float>(s0));
    }
  }
  return lut;
}

}  // namespace ris
