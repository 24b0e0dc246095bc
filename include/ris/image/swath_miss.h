// The error of a run whose swath holds no sample of the scene, one text for
// the SLAR/SAR line engine, the older whole-geometry image and the PPI
// (issue 38: the copies drifted, and a scene wholly out of view printed
// "slant range inf to -inf m").
//
// Example:
//   if (in_swath == 0) ris::throw_swath_misses_scene(file, p.range, r_min, r_max, "track");
#pragma once

#include <string>

#include "ris/geometry/slant_range_bins.h"

namespace ris {

// r_min_m .. r_max_m: the slant-range extent of the samples with data in
// view (r_min_m > r_max_m, e.g. +inf / -inf, when there is none). With
// samples in view the swath is wrong: `sweep_delay` is named with both
// extents. With none, no swath can help: `view_key` (the keys that place
// the radar, e.g. "track" or "position") is named instead.
[[noreturn]] void throw_swath_misses_scene(const std::string& radar_file,
                                           const SlantRangeBins& swath, double r_min_m,
                                           double r_max_m, const std::string& view_key);

}  // namespace ris
