// The terrain's slope at every scene cell, from central differences.
//
// The facet normal of MODEL.md section 2 is n ~ (-dz/dx, -dz/dy, 1); this
// file computes dz/dx (east) and dz/dy (north) once per scene. Central
// differences (z[c+1] - z[c-1]) / (2 dx) are used where both neighbours hold
// data, a one-sided difference where only one does, and 0 (level) where
// neither does; a no-data cell's own gradient is NaN. On a plane every
// interior cell gets the exact slope, so the "45 deg slope has local incidence
// theta - 45 deg" test holds to rounding.
//
// Example:
//   ris::SurfaceGradient g = ris::surface_gradient(scene);
//   float dzdx = g.dz_dx[scene.index(r, c)];
#pragma once

#include <vector>

#include "ris/scene/scene.h"

namespace ris {

struct SurfaceGradient {
  std::vector<float> dz_dx;  // rows*cols, metres per metre towards east (+x)
  std::vector<float> dz_dy;  // rows*cols, metres per metre towards north (+y)
};

SurfaceGradient surface_gradient(const Scene& scene);

}  // namespace ris
