#include "ris/geometry/scene_geometry_maps.h"

#include <cmath>
#include <limits>

#include "ris/util/units.h"

namespace ris {

SceneGeometryMaps scene_geometry_maps(const Scene& scene, const SlarGeometry& g,
                                      const SlantRangeBins& bins) {
  SceneGeometryMaps m;
  m.mask.assign(scene.size(), 0);
  m.local_incidence_deg.assign(scene.size(), std::numeric_limits<float>::quiet_NaN());
  const double far = bins.far_m();
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      const std::size_t cell = scene.index(r, c);
      int line = 0, sample = 0;
      if (!scene_cell_sample(scene, g, r, c, line, sample)) {
        m.mask[cell] = (scene.valid[cell] ? 0 : scene_flag::kNoData) | scene_flag::kOutsideSwath;
        continue;
      }
      const std::size_t i = g.index(line, sample);
      scene_map_cell(scene.valid[cell] != 0, g.flags[i], g.slant_range_m[i],
                     g.local_incidence_rad[i], bins.near_m, far, m.mask[cell],
                     m.local_incidence_deg[cell]);
    }
  }
  return m;
}

}  // namespace ris
