// The terrain at one ground point between cell centres: bilinear elevation
// and slope, the nearest cell's category (MODEL.md section 2, "Tracks that
// are not along a grid axis"). Shared by the SLAR/SAR line sampler for
// headings off the grid axes and by the PPI rays.
//
// Example:
//   const ris::SurfaceGradient grad = ris::surface_gradient(scene);
//   ris::TerrainSample t = ris::bilinear_terrain_sample(scene, &grad, x_m, y_m);
//   if (t.valid) use(t.height_m, t.dz_dx, t.dz_dy, t.category);
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "ris/geometry/surface_gradient.h"
#include "ris/scene/scene.h"

namespace ris {

struct TerrainSample {
  bool inside = false;  // within the scene
  bool valid = false;   // has data
  float height_m = 0.0f;
  float dz_dx = 0.0f;
  float dz_dy = 0.0f;
  std::uint16_t category = 0;
};

// Cell centres sit at integer + 1/2 grid coordinates; points between the
// outermost centres and the scene edge take the outermost centres' values.
// A point whose interpolation touches a no-data cell has no data. grad may be
// null when only the height and category are wanted (slopes are then 0).
// Inline: the fused oblique path calls it 2.7 times per scene cell.
inline TerrainSample bilinear_terrain_sample(const Scene& scene, const SurfaceGradient* grad,
                                             double x_m, double y_m) {
  TerrainSample ts;
  const auto [cf, rf] = scene.grid_from_world(x_m, y_m);
  const int cols = scene.cols, rows = scene.rows;
  if (!(cf >= 0.0 && cf <= cols && rf >= 0.0 && rf <= rows)) return ts;
  ts.inside = true;
  // Cell centres sit at integer + 0.5; clamp to the outermost centres.
  const double px = std::clamp(cf - 0.5, 0.0, double(cols - 1));
  const double py = std::clamp(rf - 0.5, 0.0, double(rows - 1));
  const int c0 = std::min(static_cast<int>(px), std::max(cols - 2, 0));
  const int r0 = std::min(static_cast<int>(py), std::max(rows - 2, 0));
  const int c1 = std::min(c0 + 1, cols - 1), r1 = std::min(r0 + 1, rows - 1);
  const double fx = px - c0, fy = py - r0;
  const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
  const std::size_t idx[4] = {scene.index(r0, c0), scene.index(r0, c1), scene.index(r1, c0),
                              scene.index(r1, c1)};
  double h = 0.0, gx = 0.0, gy = 0.0;
  for (int k = 0; k < 4; ++k) {
    if (w[k] <= 0.0) continue;
    if (!scene.valid[idx[k]]) return ts;  // touches no data
    h += w[k] * scene.elevation_m[idx[k]];
    if (grad) {
      gx += w[k] * grad->dz_dx[idx[k]];
      gy += w[k] * grad->dz_dy[idx[k]];
    }
  }
  const int cn = std::min(static_cast<int>(cf), cols - 1);
  const int rn = std::min(static_cast<int>(rf), rows - 1);
  ts.valid = true;
  ts.height_m = static_cast<float>(h);
  ts.dz_dx = static_cast<float>(gx);
  ts.dz_dy = static_cast<float>(gy);
  ts.category = scene.category[scene.index(rn, cn)];
  return ts;
}

}  // namespace ris
