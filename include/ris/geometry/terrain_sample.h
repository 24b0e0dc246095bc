// The terrain at one ground point between cell centres: bilinear elevation
// and slope, the nearest cell's category (MODEL.md section 2, "Tracks that
// are not along a grid axis"). bilinear_cells is the one rule for which
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
// `nearest` is the cell that contains the point (floor(col), floor(row),
// clamped to the grid). The position is in double (exact to 1e-12 cells on
// any scene size); the weights are float, the precision of the rasters they
// weight. The caller checks 0 <= col <= cols, 0 <= row <= rows. Index: the
// integer type of cell indices (the line sampler's vector loop uses 32-bit
// ones where they fit). Selects only, no branches, so that a loop over
// samples vectorises.
template <typename Index>
struct BilinearCells {
  Index cell00 = 0;    // Scene::index of (r0, c0)
  Index step_col = 0;  // to (r0, c1): 1, or 0 in a scene one cell wide
  Index step_row = 0;  // to (r1, c0): cols, or 0 in a scene one cell tall
  Index nearest = 0;   // Scene::index of the cell containing the point
  float weight[4] = {0.0f, 0.0f, 0.0f, 0.0f};
};

template <typename Index>
inline BilinearCells<Index> bilinear_cells(int rows, int cols, double col, double row) {
  // Cell centres sit at integer + 0.5; clamp to the outermost centres.
  // (Selects of values, not std::min/max, which return references: GCC
  // keeps those in memory and will not vectorise the caller's loop.)
  const auto clamp = [](double v, double hi) { return v < 0.0 ? 0.0 : (v > hi ? hi : v); };
  const auto at_most = [](int v, int hi) { return v < hi ? v : hi; };
  const double px = clamp(col - 0.5, double(cols - 1));
  const double py = clamp(row - 0.5, double(rows - 1));
  const int c0 = at_most(static_cast<int>(px), cols > 2 ? cols - 2 : 0);
  const int r0 = at_most(static_cast<int>(py), rows > 2 ? rows - 2 : 0);
  // Exact in double (px - c0 is in [0, 1]). floor(col) is c1 exactly when
  // px - c0 >= 0.5 (col - 0.5 is exact for col >= 0.5, and clamping keeps
  // the outermost cell).
  const double fxd = px - c0, fyd = py - r0;
  const auto fx = static_cast<float>(fxd), fy = static_cast<float>(fyd);
  BilinearCells<Index> b;
  b.step_col = cols > 1 ? Index{1} : Index{0};
  b.step_row = rows > 1 ? static_cast<Index>(cols) : Index{0};
  b.cell00 = static_cast<Index>(r0) * static_cast<Index>(cols) + static_cast<Index>(c0);
  b.nearest =
      b.cell00 + (fxd >= 0.5 ? b.step_col : Index{0}) + (fyd >= 0.5 ? b.step_row : Index{0});
  b.weight[0] = (1.0f - fx) * (1.0f - fy);
  b.weight[1] = fx * (1.0f - fy);
  b.weight[2] = (1.0f - fx) * fy;
  b.weight[3] = fx * fy;
  return b;
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
  const auto b = bilinear_cells<std::size_t>(scene.rows, scene.cols, cf, rf);
  const std::size_t index[4] = {b.cell00, b.cell00 + b.step_col, b.cell00 + b.step_row,
                                b.cell00 + b.step_row + b.step_col};
  float h = 0.0f, gx = 0.0f, gy = 0.0f;
  for (int k = 0; k < 4; ++k) {
    const float w = b.weight[k];
    const std::size_t i = index[k];
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
  ts.category = scene.category[b.nearest];
  return ts;
}

}  // namespace ris
