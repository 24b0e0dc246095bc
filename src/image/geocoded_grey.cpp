#include "ris/image/geocoded_grey.h"

#include <cmath>

namespace ris {

std::vector<std::uint8_t> geocoded_validity(std::span<const float> geocoded_power_w) {
  std::vector<std::uint8_t> valid(geocoded_power_w.size());
  for (std::size_t i = 0; i < valid.size(); ++i) valid[i] = std::isnan(geocoded_power_w[i]) ? 0 : 1;
  return valid;
}

GeocodedGrey geocoded_grey(const Scene& scene, const Track& track, const SlarImage& image,
                           std::span<const std::uint8_t> slant_grey,
                           std::span<const float> slant_power_w, GeocodeResampling resampling) {
  GeocodedGrey g;
  g.grey = geocode_slant_grey(scene, track, image, slant_grey, 0, resampling);
  g.valid = geocoded_validity(geocode_slant_image(scene, track, image, slant_power_w, resampling));
  return g;
}

}  // namespace ris
