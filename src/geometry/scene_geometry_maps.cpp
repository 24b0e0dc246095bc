#include "ris/geometry/scene_geometry_maps.h"

#include <cmath>
#include <limits>

#include "ris/util/units.h"

namespace ris {

CellSampleFrame cell_sample_frame(const Scene& scene, const SlarGeometry& g) {
  const Track& t = g.track;
  CellSampleFrame f;
  const auto [x, y] = scene.cell_centre(0, 0);
  const auto [s, u] = t.along_cross(x, y);
  f.line0 = s / g.line_spacing_m - 0.5;
  f.sample0 = (u - g.first_sample_u_m) / g.sample_step_m;
  // One column east is +dx in x, one row south -dy in y.
  f.line_dc = scene.dx_m * t.along_x / g.line_spacing_m;
  f.line_dr = -scene.dy_m * t.along_y / g.line_spacing_m;
  f.sample_dc = scene.dx_m * t.cross_x / g.sample_step_m;
  f.sample_dr = -scene.dy_m * t.cross_y / g.sample_step_m;
  f.lines = g.lines;
  f.samples = g.samples;
  return f;
}

SceneGeometryMaps scene_geometry_maps(const Scene& scene, const SlarGeometry& g,
                                      const SlantRangeBins& bins) {
  SceneGeometryMaps m;
  m.mask.assign(scene.size(), 0);
  m.local_incidence_deg.assign(scene.size(), std::numeric_limits<float>::quiet_NaN());
  const double far = bins.far_m();
  const CellSampleFrame frame = cell_sample_frame(scene, g);
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      const std::size_t cell = scene.index(r, c);
      int line = 0, sample = 0;
      if (!cell_sample(frame, r, c, line, sample)) {
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
