#include "ris/geometry/surface_gradient.h"

#include <cmath>
#include <limits>

namespace ris {

SurfaceGradient surface_gradient(const Scene& scene) {
  SurfaceGradient g;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  g.dz_dx.assign(scene.size(), nan);
  g.dz_dy.assign(scene.size(), nan);
  const auto ok = [&](int r, int c) {
    return scene.contains(r, c) && scene.valid[scene.index(r, c)];
  };
  const auto z = [&](int r, int c) {
    return scene.contains(r, c) ? scene.elevation_m[scene.index(r, c)] : 0.0f;
  };
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      if (!ok(r, c)) continue;
      const std::size_t i = scene.index(r, c);
      const float zc = scene.elevation_m[i];
      g.dz_dx[i] =
          slope_difference(ok(r, c - 1), z(r, c - 1), ok(r, c + 1), z(r, c + 1), zc, scene.dx_m);
      // North (+y) is towards row r - 1.
      g.dz_dy[i] =
          slope_difference(ok(r + 1, c), z(r + 1, c), ok(r - 1, c), z(r - 1, c), zc, scene.dy_m);
    }
  }
  return g;
}

}  // namespace ris
