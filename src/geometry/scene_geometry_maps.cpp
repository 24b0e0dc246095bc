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
      std::uint8_t f = scene.valid[cell] ? 0 : scene_flag::kNoData;
      const auto [x, y] = scene.cell_centre(r, c);
      const auto [s, u] = g.track.along_cross(x, y);
      const double line = std::round(s / g.line_spacing_m - 0.5);
      const double sample = std::round((u - g.first_sample_u_m) / g.sample_step_m);
      if (!(line >= 0 && line < g.lines && sample >= 0 && sample < g.samples)) {
        m.mask[cell] = f | scene_flag::kOutsideSwath;
        continue;
      }
      const std::size_t i = g.index(static_cast<int>(line), static_cast<int>(sample));
      const std::uint8_t sf = g.flags[i];
      if (sf & sample_flag::kNoData) f |= scene_flag::kNoData;
      if (sf & sample_flag::kShadow) f |= scene_flag::kShadow;
      if (sf & sample_flag::kLayover) f |= scene_flag::kLayover;
      if (sf & sample_flag::kBackFacing) f |= scene_flag::kBackFacing;
      const double R = g.slant_range_m[i];
      const bool has_data = !(sf & (sample_flag::kNoData | sample_flag::kUnseen));
      if ((sf & sample_flag::kUnseen) || (has_data && !(R >= bins.near_m && R < far))) {
        f |= scene_flag::kOutsideSwath;
      }
      if (!(sf & (sample_flag::kNoData | sample_flag::kUnseen)) && !(f & scene_flag::kNoData)) {
        m.local_incidence_deg[cell] = static_cast<float>(rad_to_deg(g.local_incidence_rad[i]));
      }
      m.mask[cell] = f;
    }
  }
  return m;
}

}  // namespace ris
