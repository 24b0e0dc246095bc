// Shaded relief of a scene: the cosine of the angle between each cell's
// surface normal and a distant light, for pictures.
//
// The normal is MODEL.md section 2's facet normal n ~ (-dz/dx, -dz/dy, 1)
// from central differences (one-sided at the grid's edges and next to
// no-data cells); the light comes from azimuth `azimuth_deg` (clockwise from
// north; 315 = north-west, the cartographers' convention) at
// `altitude_deg` above the horizon. Flat ground shades to sin(altitude).
//
// Example:
//   std::vector<float> shade = ris::hillshade(scene);  // 0 (dark) .. 1 (lit)
#pragma once

#include <vector>

#include "ris/scene/scene.h"

namespace ris {

// One value per cell in [0, 1]; 0 for no-data cells.
std::vector<float> hillshade(const Scene& scene, double azimuth_deg = 315.0,
                             double altitude_deg = 45.0);

}  // namespace ris
