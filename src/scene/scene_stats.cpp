#include "ris/scene/scene_stats.h"

#include <algorithm>
#include <limits>

namespace ris {

SceneStats scene_stats(const Scene& scene) {
  SceneStats st;
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  double sum = 0.0;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (scene.valid[i] == 0) {
      ++st.nodata_cells;
      continue;
    }
    ++st.valid_cells;
    const double z = scene.elevation_m[i];
    lo = std::min(lo, z);
    hi = std::max(hi, z);
    sum += z;
    ++st.category_counts[scene.category[i]];
  }
  if (st.valid_cells > 0) {
    st.min_elevation_m = lo;
    st.max_elevation_m = hi;
    st.mean_elevation_m = sum / static_cast<double>(st.valid_cells);
  }
  return st;
}

}  // namespace ris
