#include "ris/image/hillshade.h"

#include <algorithm>
#include <cmath>

#include "ris/util/units.h"

namespace ris {

std::vector<float> hillshade(const Scene& scene, double azimuth_deg, double altitude_deg) {
  const double az = deg_to_rad(azimuth_deg);
  const double alt = deg_to_rad(altitude_deg);
  // Light direction in (east, north, up).
  const double lx = std::sin(az) * std::cos(alt);
  const double ly = std::cos(az) * std::cos(alt);
  const double lz = std::sin(alt);
  std::vector<float> shade(scene.size(), 0.0f);
  const int rows = scene.rows;
  const int cols = scene.cols;
  auto usable = [&](int r, int c) {
    return scene.contains(r, c) && scene.valid[scene.index(r, c)];
  };
  auto z = [&](int r, int c) { return static_cast<double>(scene.elevation_m[scene.index(r, c)]); };

#pragma omp parallel for schedule(static)
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      if (!usable(r, c)) continue;
      // dz/dx (east): central difference, one-sided where a neighbour is missing.
      const int cw = usable(r, c - 1) ? c - 1 : c;
      const int ce = usable(r, c + 1) ? c + 1 : c;
      const double dzdx = ce > cw ? (z(r, ce) - z(r, cw)) / ((ce - cw) * scene.dx_m) : 0.0;
      // dz/dy (north = towards row 0).
      const int rn = usable(r - 1, c) ? r - 1 : r;
      const int rs = usable(r + 1, c) ? r + 1 : r;
      const double dzdy = rs > rn ? (z(rn, c) - z(rs, c)) / ((rs - rn) * scene.dy_m) : 0.0;
      const double nx = -dzdx, ny = -dzdy, nz = 1.0;
      const double cosine = (nx * lx + ny * ly + nz * lz) / std::sqrt(nx * nx + ny * ny + nz * nz);
      shade[scene.index(r, c)] = static_cast<float>(std::max(0.0, cosine));
    }
  }
  return shade;
}

}  // namespace ris
