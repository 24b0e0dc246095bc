#include "ris/image/greytone_image.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>

#include "ris/image/speckle.h"
#include "ris/sensor/radar_derived.h"
#include "ris/util/error.h"

namespace ris {

std::vector<double> looks_per_bin(const RadarParams& radar, int bins, double near_range_m,
                                  double bin_m) {
  std::vector<double> looks(static_cast<std::size_t>(std::max(bins, 0)));
  for (int k = 0; k < bins; ++k) {
    looks[static_cast<std::size_t>(k)] =
        independent_samples(radar, near_range_m + (k + 0.5) * bin_m);
  }
  return looks;
}

GreytoneImage make_greytone_image(const RadarParams& radar, std::span<const float> mean_power_w,
                                  int lines, int bins, double near_range_m, double bin_m,
                                  std::uint64_t seed, std::span<const std::uint8_t> no_data) {
  return make_greytone_image(radar, mean_power_w, lines, bins,
                             looks_per_bin(radar, bins, near_range_m, bin_m), seed, no_data);
}

GreytoneImage make_greytone_image(const RadarParams& radar, std::span<const float> mean_power_w,
                                  int lines, int bins, std::vector<double> looks,
                                  std::uint64_t seed, std::span<const std::uint8_t> no_data) {
  RIS_CHECK(lines >= 0 && bins >= 0);
  RIS_CHECK(looks.size() == static_cast<std::size_t>(bins));
  RIS_CHECK(mean_power_w.size() ==
            static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins));
  RIS_CHECK(no_data.empty() || no_data.size() == mean_power_w.size());
  // The reference comes from the mean power, so the grey scale does not
  // depend on the fading seed.
  GreytoneImage out{{}, {}, {}, make_greytone_map(radar, mean_power_w, no_data)};
  out.looks_per_bin = std::move(looks);
  out.speckled_power_w.assign(mean_power_w.begin(), mean_power_w.end());
  if (!no_data.empty()) {
    for (std::size_t i = 0; i < no_data.size(); ++i) {
      if (no_data[i] != 0) out.speckled_power_w[i] = std::numeric_limits<float>::quiet_NaN();
    }
  }
  if (radar.switches.fading) {
    apply_fading(out.speckled_power_w, lines, bins, out.looks_per_bin, radar.fading, seed);
  }
  out.greytone.resize(mean_power_w.size());
  greytones(out.speckled_power_w, out.greytone, out.map, no_data);
  return out;
}

}  // namespace ris
