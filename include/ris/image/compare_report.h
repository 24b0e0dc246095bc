// The measures of `ris compare` (docs/quality.md, "ris compare") as one JSON
// object, so that the command line (apps/ris/cmd_compare.cpp) and the Python
// API (ris.compare) report the same numbers from the same code:
// co-registration, windowed agreement of the dB images, histogram distance,
// per-category bias, shadow/layover mask agreement and the geometry-only
// baselines.
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <vector>

namespace ris {

struct CompareRequest {
  bool register_images = true;                  // false: take the images as aligned
  int max_shift_px = 16;                        // largest shift searched (1 or more)
  std::span<const double> categories;           // empty: no per-category bias
  std::span<const double> mask;                 // the simulation's mask values; empty: none
  std::span<const double> local_incidence_deg;  // empty: no baselines
};

struct CompareReport {
  nlohmann::json measures;          // "registration" (when registered), "agreement",
                                    // "histogram_hellinger", "category_bias", "masks", "baselines"
  std::vector<float> real_aligned;  // the real intensity moved onto the simulation's grid
};

// 10 log10 of positive finite values, NaN elsewhere.
std::vector<float> intensity_to_db(std::span<const float> v);

// `simulated` and `real`: intensities on the same cols x rows grid; the
// request's rasters on that grid too. Throws InputError (key "max_shift")
// for a bad request.
CompareReport compare_measures(std::span<const float> simulated, std::span<const float> real,
                               int cols, int rows, const CompareRequest& request);

}  // namespace ris
