// The geocoded greytone image and its validity: which scene cells hold a
// pixel with data. Every greytone is a valid value (0 is black: shadow), so
// geocoded_grey.tif says which cells have no pixel with a mask band, not a
// no-data value (docs/outputs.md).
//
// Example:
//   const ris::GeocodedGrey g = ris::geocoded_grey(scene, sim.track, sim.image,
//                                                  pic.slant_grey, pic.speckled_power_w);
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ris/image/geocode.h"

namespace ris {

struct GeocodedGrey {
  std::vector<std::uint8_t> grey;   // rows x cols, 0 where no pixel
  std::vector<std::uint8_t> valid;  // 1 where the cell's geocoded power has data
};

// slant_grey, slant_power_w: the slant-range greytones and the power they
// were made from (NaN where no data), lines x bins.
GeocodedGrey geocoded_grey(const Scene& scene, const Track& track, const SlarImage& image,
                           std::span<const std::uint8_t> slant_grey,
                           std::span<const float> slant_power_w,
                           GeocodeResampling resampling = GeocodeResampling::nearest);

// The validity of a block of geocoded power (1 finite, 0 NaN): what a
// streamed run's block of geocoded_grey.tif takes as its mask.
std::vector<std::uint8_t> geocoded_validity(std::span<const float> geocoded_power_w);

}  // namespace ris
