#include "ris/geometry/surface_gradient.h"

#include <cmath>
#include <limits>
#include <tuple>

namespace ris {

SurfaceGradient surface_gradient(const Scene& scene) {
  SurfaceGradient g;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  g.dz_dx.assign(scene.size(), nan);
  g.dz_dy.assign(scene.size(), nan);
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      const std::size_t i = scene.index(r, c);
      if (!scene.valid[i]) continue;
      std::tie(g.dz_dx[i], g.dz_dy[i]) = cell_slope(scene, r, c);
    }
  }
  return g;
}

}  // namespace ris
