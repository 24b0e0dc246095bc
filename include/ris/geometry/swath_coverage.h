// How much of a scene a SLAR/SAR swath images, for the warning a run gives
// when it is less than half (issue 38: the radar example in docs/python.md
// imaged 1.8 km of a 5 km scene and missed its hill, silently).
//
// On flat ground at the reference height h (the run's: the median elevation),
// slant range R is ground distance u = sqrt(R^2 - (H - h)^2) from the
// track (MODEL.md section 2, "Straight, level track"), so the swath
// R_near .. R_far images the ground band u_near .. u_far, along the track
// from its start (s = 0) to its end (s = length). A cell is imaged when its
// centre lies in that band.
//
// Example:
//   const ris::SwathCoverage c = ris::swath_coverage(track, grid, range, h_ref_m);
//   if (auto w = ris::swath_coverage_warning(c)) sim.warnings.push_back(*w);
#pragma once

#include <optional>
#include <string>

#include "ris/geometry/slant_range_bins.h"
#include "ris/scene/scene.h"
#include "ris/sensor/track.h"

namespace ris {

struct SwathCoverage {
  double cell_fraction = 1.0;  // of the scene's cells (sampled on at most 512 x 512)
  double across_scene_m = 0.0, across_imaged_m = 0.0;
  double along_scene_m = 0.0, along_imaged_m = 0.0;
  bool misses_near = false;  // scene ground nearer the track than the swath's near edge
  bool misses_far = false;   // and farther than its far edge
  double reference_height_m = 0.0;
};

SwathCoverage swath_coverage(const Track& track, const Scene& grid, const SlantRangeBins& swath,
                             double reference_height_m);

// The warning when less than half of the scene's cells are imaged, saying
// which part is and what to change; nullopt otherwise.
std::optional<std::string> swath_coverage_warning(const SwathCoverage& c);

}  // namespace ris
