// Summary statistics of a scene: elevation range, category histogram,
// no-data count (for `ris scene info` and for pinning scenes in tests).
//
// Example:
//   ris::SceneStats st = ris::scene_stats(scene);
//   fmt::print("{} .. {} m\n", st.min_elevation_m, st.max_elevation_m);
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>

#include "ris/scene/scene.h"

namespace ris {

struct SceneStats {
  std::size_t valid_cells = 0;
  std::size_t nodata_cells = 0;
  double min_elevation_m = 0.0;  // over valid cells; 0 when none is valid
  double max_elevation_m = 0.0;
  double mean_elevation_m = 0.0;
  std::map<std::uint16_t, std::size_t> category_counts;  // valid cells only
};

SceneStats scene_stats(const Scene& scene);

}  // namespace ris
