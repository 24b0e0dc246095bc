// Where a run's inputs came from and how its pictures are written: read by
// metadata.json (ris/sim/run_metadata.h) and by the product writers
// (ris/sim/slar_products.h, ris/sim/ppi_products.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "ris/image/geocode.h"
#include "ris/io/compression_preset.h"

namespace ris {

// The pictures (slant_range, ground_range) are PNG up to kMaxPngPixels
// pixels and tiled compressed GeoTIFFs of the same greytones above (a PNG is
// one zlib stream: slow to write and to open at that size, where a tiled
// GeoTIFF opens at any zoom in a GIS). picture_file gives the file name.
inline constexpr std::int64_t kMaxPngPixels = std::int64_t(1) << 28;  // 268 M, 16384^2

// Which products a run writes (`ris simulate --products`): file stems as
// docs/outputs.md lists them ("slant_range", "scene_mask", ...); empty: all.
// metadata.json is always written and lists the products written.
struct ProductSelection {
  std::vector<std::string> stems;
  bool wants(std::string_view stem) const;
};

// Checks a selection against a mode's product stems; throws InputError
// naming `key` and listing the allowed stems.
void check_product_selection(const ProductSelection& selection,
                             const std::vector<std::string_view>& allowed, const std::string& key);

// Removes from `folder` the products `selection` does not want (files whose
// stem it does not list; metadata.json and hidden files kept): a streamed
// run writes the products later passes read back, then drops those not
// selected before its staged folder commits.
void remove_unselected_products(const std::filesystem::path& folder,
                                const ProductSelection& selection);

// Where the inputs came from, for metadata.json, and how the products are
// written.
struct SlarRunInfo {
  std::string scene_path;
  std::string radar_path;
  std::string backscatter_path;
  std::uint64_t seed = 0;
  int threads = 0;
  // Pictures larger than this are GeoTIFFs (picture_file; tests lower it).
  std::int64_t max_png_pixels = kMaxPngPixels;
  ProductSelection products = {};
  CompressionPreset compression = CompressionPreset::fast;
  // Internal overviews on large GeoTIFF products (`--no-overviews`: off).
  bool overviews = true;
  // How the geocoded products take their pixels (`--geocode-resampling`).
  GeocodeResampling geocode_resampling = GeocodeResampling::nearest;
  // Also the calibrated images, sigma0/beta0/gamma0 linear and in dB
  // (`--calibrated`; ris/sim/slar_products.h wants_calibrated).
  bool calibrated = false;
};

// The GeoTIFF settings of a run's products: its compression preset for
// floating-point or integer samples, with overviews unless turned off.
GeoTiffCompression product_tiff_settings(const SlarRunInfo& info, bool floating_point);

}  // namespace ris
