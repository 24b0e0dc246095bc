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
TerrainSample bilinear_terrain_sample(const Scene& scene, const SurfaceGradient* grad, double x_m,
                                      double y_m);

}  // namespace ris
