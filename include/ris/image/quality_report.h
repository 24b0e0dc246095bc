// The measures of `ris quality` (docs/quality.md) as one JSON object, so that
// the command line (apps/ris/cmd_quality.cpp) and the Python API
// (python/ris_module.cpp, ris.quality) report the same numbers from the same
// code: speckle over homogeneous regions, the dB histogram, per-category
// statistics and pair separability, edge sharpness across a mask's edges,
// and point-target impulse responses.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <span>
#include <utility>
#include <vector>

#include "ris/image/speckle_statistics.h"

namespace ris {

struct QualityRequest {
  std::vector<PixelBox> regions;             // empty: automatic homogeneous windows
  int window = 16;                           // side of the automatic windows, pixels (4 or more)
  std::span<const double> categories;        // empty: no per-category statistics
  int mask_bit = 1;                          // mask bit whose edges are measured (with a mask)
  std::vector<std::pair<int, int>> targets;  // (line, bin) of point targets
  double line_spacing_m = 1.0, range_bin_m = 1.0;  // pixel sizes of the impulse responses
};

// Keys "speckle", "histogram", and with the request's inputs "categories" and
// "pairs", "edges" (when `view.mask` is not empty) and "targets". Throws
// InputError (key "window", "regions" or "target") for a bad request.
// A mask raster's values as the mask bits quality_measures reads; non-finite
// values count as no data (bit 4).
std::vector<std::uint8_t> quality_mask_bits(std::span<const double> values);

nlohmann::json quality_measures(const IntensityView& view, const QualityRequest& request);

}  // namespace ris
