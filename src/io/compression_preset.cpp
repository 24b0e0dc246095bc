#include "ris/io/compression_preset.h"

#include <array>
#include <utility>
#include <vector>

#include "ris/io/config_table.h"
#include "ris/util/error.h"

namespace ris {

GeoTiffCompression geotiff_compression(CompressionPreset preset, bool floating_point) {
  GeoTiffCompression c;
  switch (preset) {
    case CompressionPreset::fast:
      return c;
    case CompressionPreset::small:
      // ZSTD with the predictor that suits the samples (3: floating point,
      // 2: horizontal differencing of integers) at level 9.
      c.method = "ZSTD";
      c.level = 9;
      c.predictor = floating_point ? 3 : 2;
      return c;
    case CompressionPreset::none:
      c.method = "NONE";
      return c;
  }
  return c;
}

int png_compression_level(CompressionPreset preset) {
  switch (preset) {
    case CompressionPreset::fast:
      return kDefaultPngLevel;
    case CompressionPreset::small:
      return 3;  // measured smaller than 6 and 9 on ris's pictures
    case CompressionPreset::none:
      return 1;  // GDAL's PNG driver takes ZLEVEL 1 to 9 only
  }
  return 6;
}

namespace {
constexpr std::array<std::pair<std::string_view, CompressionPreset>, 3> kPresets = {{
    {"fast", CompressionPreset::fast},
    {"small", CompressionPreset::small},
    {"none", CompressionPreset::none},
}};
}  // namespace

std::string_view to_string(CompressionPreset preset) {
  for (const auto& [name, value] : kPresets)
    if (value == preset) return name;
  return "?";
}

CompressionPreset parse_compression_preset(std::string_view text, const std::string& key) {
  std::vector<std::string_view> names;
  for (const auto& [name, value] : kPresets) {
    if (name == text) return value;
    names.push_back(name);
  }
  throw InputError(
      "", key, "expected " + quoted_alternatives(names) + ", got \"" + std::string(text) + "\"");
}

}  // namespace ris
