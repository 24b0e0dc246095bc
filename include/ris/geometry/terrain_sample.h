// The terrain at one ground point between cell centres: bilinear elevation
// and slope, the nearest cell's category (MODEL.md section 2, "Tracks that
// are not along a grid axis"). bilinear_footprint is the one rule for which
// cells and weights a point takes; it is shared by this single-point sampler
// (PPI sites, point targets) and the line sampler of SLAR/SAR lines off the
// grid axes and PPI rays (ris/geometry/terrain_line.h).
//
// Example:
//   ris::TerrainSample t = ris::bilinear_terrain_sample(scene, nullptr, x_m, y_m);
//   if (t.valid) use(t.height_m, t.category);
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

// The four cells around grid position (col, row) (grid_from_world's
// coordinates, cell centres at integer + 1/2) and their bilinear weights, in
// the order (r0, c0), (r0, c1), (r1, c0), (r1, c1). Points between the
// outermost centres and the scene edge take the outermost centres' values
// (clamped, so a weight may be 0; a scene one cell wide repeats the cell).
// `nearest` is the corner whose cell contains the point (floor(col),
// floor(row), clamped to the grid). The position is in double (exact to
// 1e-12 cells on any scene size); the weights are float, the precision of
// the rasters they weight. The caller checks 0 <= col <= cols, 0 <= row <= rows.
struct BilinearFootprint {
  std::size_t index[4];  // Scene::index of the four cells
  float weight[4];
  int nearest = 0;  // 0..3
};

inline BilinearFootprint bilinear_footprint(int rows, int cols, double col, double row) {
  // Cell centres sit at integer + 0.5; clamp to the outermost centres.
  const double px = std::clamp(col - 0.5, 0.0, double(cols - 1));
  const double py = std::clamp(row - 0.5, 0.0, double(rows - 1));
  const int c0 = std::min(static_cast<int>(px), std::max(cols - 2, 0));
  const int r0 = std::min(static_cast<int>(py), std::max(rows - 2, 0));
  const int c1 = std::min(c0 + 1, cols - 1), r1 = std::min(r0 + 1, rows - 1);
  // Exact in double (px - c0 is in [0, 1]); then the nearest cell: floor(col)
  // is c1 exactly when col - 0.5 - c0 >= 0.5 (col - 0.5 is exact for col >=
  // 0.5, and clamping keeps the outermost cell).
  const double fxd = px - c0, fyd = py - r0;
  const auto fx = static_cast<float>(fxd), fy = static_cast<float>(fyd);
  BilinearFootprint fp;
  const auto cols_z = static_cast<std::size_t>(cols);
  const std::size_t row0 = static_cast<std::size_t>(r0) * cols_z;
  const std::size_t row1 = static_cast<std::size_t>(r1) * cols_z;
  fp.index[0] = row0 + static_cast<std::size_t>(c0);
  fp.index[1] = row0 + static_cast<std::size_t>(c1);
  fp.index[2] = row1 + static_cast<std::size_t>(c0);
  fp.index[3] = row1 + static_cast<std::size_t>(c1);
  fp.weight[0] = (1.0f - fx) * (1.0f - fy);
  fp.weight[1] = fx * (1.0f - fy);
  fp.weight[2] = (1.0f - fx) * fy;
  fp.weight[3] = fx * fy;
  fp.nearest = (fxd >= 0.5 ? 1 : 0) + (fyd >= 0.5 ? 2 : 0);
  return fp;
}

// A point whose interpolation touches (with a weight above 0) a no-data cell
// has no data. grad may be null when only the height and category are wanted
// (slopes are then 0). Sums in float in corner order, as the line sampler.
inline TerrainSample bilinear_terrain_sample(const Scene& scene, const SurfaceGradient* grad,
                                             double x_m, double y_m) {
  TerrainSample ts;
  const auto [cf, rf] = scene.grid_from_world(x_m, y_m);
  if (!(cf >= 0.0 && cf <= scene.cols && rf >= 0.0 && rf <= scene.rows)) return ts;
  ts.inside = true;
  const BilinearFootprint fp = bilinear_footprint(scene.rows, scene.cols, cf, rf);
  float h = 0.0f, gx = 0.0f, gy = 0.0f;
  for (int k = 0; k < 4; ++k) {
    const float w = fp.weight[k];
    const std::size_t i = fp.index[k];
    if (!(w > 0.0f)) continue;
    if (!scene.valid[i]) return ts;  // touches no data
    h += w * scene.elevation_m[i];
    if (grad) {
      gx += w * grad->dz_dx[i];
      gy += w * grad->dz_dy[i];
    }
  }
  ts.valid = true;
  ts.height_m = h;
  ts.dz_dx = gx;
  ts.dz_dy = gy;
  ts.category = scene.category[fp.index[fp.nearest]];
  return ts;
}

}  // namespace ris
