#include "ris/image/swath_miss.h"

#include <fmt/format.h>

#include <cmath>

#include "ris/util/error.h"

namespace ris {

void throw_swath_misses_scene(const std::string& radar_file, const SlantRangeBins& swath,
                              double r_min_m, double r_max_m, const std::string& view_key) {
  if (std::isfinite(r_min_m) && std::isfinite(r_max_m) && r_min_m <= r_max_m) {
    throw InputError(radar_file, "sweep_delay",
                     fmt::format("the swath (slant range {:.1f} to {:.1f} m) misses the scene, "
                                 "which spans slant range {:.1f} to {:.1f} m; expected a sweep "
                                 "delay and length (or near range and range bins) that overlap it",
                                 swath.near_m, swath.far_m(), r_min_m, r_max_m));
  }
  throw InputError(radar_file, view_key,
                   fmt::format("no cell of the scene with data is in view of the radar, so the "
                               "swath (slant range {:.1f} to {:.1f} m) has nothing to image; "
                               "expected {} from which the scene is seen (is the radar on the "
                               "right side of it, and looking towards it?)",
                               swath.near_m, swath.far_m(), view_key));
}

}  // namespace ris
