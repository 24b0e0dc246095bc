// An 8-bit preview of an optical or thermal image (preview.png and
// camera_preview.png of `ris sensor`, the page's sensor view): RGB from the
// red, green and blue bands when all three are imaged, else the first band
// in grey; each stretched linearly between its 2nd and 98th percentiles
// (no data black).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace ris {

struct EoPreview {
  int channels = 1;                  // 1 grey, 3 RGB
  std::vector<std::uint8_t> pixels;  // rows x cols x channels
};

EoPreview eo_preview(const std::vector<std::string>& band_names,
                     const std::vector<std::vector<float>>& bands);

}  // namespace ris
