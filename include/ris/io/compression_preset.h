// How hard the product writers compress (`ris simulate --compress`): fast
// (the default), small (the smallest files, slower) or none. The presets'
// settings were chosen by measurement on the standard scene's and a
// 2048 x 2048 DEM's products (docs/performance.md, "Product writing").
//
// Example:
//   ris::GeoTiffCompression c = ris::geotiff_compression(ris::CompressionPreset::small, true);
#pragma once

#include <string>
#include <string_view>

#include "ris/io/geotiff_block_writer.h"

namespace ris {

enum class CompressionPreset { fast, small, none };

// The GeoTIFF creation settings of a preset for a raster of floating-point
// (true) or integer samples. fast gives GeoTiffCompression{} (the streamed
// run's writers use that too, so both paths write the same bytes).
GeoTiffCompression geotiff_compression(CompressionPreset preset, bool floating_point);

// The PNG driver's ZLEVEL for a preset (GDAL's default is 6).
int png_compression_level(CompressionPreset preset);

std::string_view to_string(CompressionPreset preset);
// "fast", "small" or "none" -> the preset; anything else throws InputError
// naming `key` and the allowed values.
CompressionPreset parse_compression_preset(std::string_view text, const std::string& key);

}  // namespace ris
