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

#include <utility>
#include <vector>

#include "ris/scene/scene.h"

namespace ris {

struct SurfaceGradient {
  std::vector<float> dz_dx;  // rows*cols, metres per metre towards east (+x)
  std::vector<float> dz_dy;  // rows*cols, metres per metre towards north (+y)
};

SurfaceGradient surface_gradient(const Scene& scene);

// The slope at a cell with data from its two neighbours along one axis (lo at
// -step_m, hi at +step_m; *_ok: the neighbour exists and has data), as above.
// Written with selects only (no branches), so that a loop over a row of cells
// vectorises; the fused SLAR path (ris/sim/slar_line_blocks.h) calls it too,
// so both paths get the same floats.
inline float slope_difference(bool lo_ok, float z_lo, bool hi_ok, float z_hi, float z_c,
                              double step_m) {
  // Bitwise, not short-circuit, logic: no control flow.
  const double a = hi_ok ? double(z_hi) : double(z_c);
  const double b = lo_ok ? double(z_lo) : double(z_c);
  const double num = (lo_ok | hi_ok) ? a - b : 0.0;
  const double den = (lo_ok & hi_ok) ? 2.0 * step_m : step_m;
  return static_cast<float>(num / den);
}

// (dz/dx, dz/dy) at cell (r, c), which has data: the rule above, shared by
// surface_gradient and the line sampler's texels (ris/geometry/terrain_line.h).
inline std::pair<float, float> cell_slope(const Scene& scene, int r, int c) {
  const auto ok = [&](int rr, int cc) {
    return scene.contains(rr, cc) && scene.valid[scene.index(rr, cc)];
  };
  const auto z = [&](int rr, int cc) {
    return scene.contains(rr, cc) ? scene.elevation_m[scene.index(rr, cc)] : 0.0f;
  };
  const float zc = scene.elevation_m[scene.index(r, c)];
  // North (+y) is towards row r - 1.
  return {slope_difference(ok(r, c - 1), z(r, c - 1), ok(r, c + 1), z(r, c + 1), zc, scene.dx_m),
          slope_difference(ok(r + 1, c), z(r + 1, c), ok(r - 1, c), z(r - 1, c), zc, scene.dy_m)};
}

}  // namespace ris
