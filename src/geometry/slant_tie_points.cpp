#include "ris/geometry/slant_tie_points.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "ris/util/error.h"

namespace ris {

CellElevation scene_elevation(const Scene& scene) {
  return [&scene](int row, int col) {
    const std::size_t i = scene.index(row, col);
    return scene.valid[i] ? scene.elevation_m[i] : std::numeric_limits<float>::quiet_NaN();
  };
}

namespace {

// The part [u0, u1] of the zero-Doppler line at s (u >= 0) inside the
// scene's rectangle; empty when u0 > u1.
std::pair<double, double> line_in_scene(const Scene& g, const Track& t, double s) {
  const auto [ax, ay] = t.world_from_along_cross(s, 0.0);
  double u0 = 0.0, u1 = std::numeric_limits<double>::infinity();
  const auto slab = [&](double a, double d, double lo, double hi) {
    if (std::abs(d) < 1e-12) {
      if (a < lo || a > hi) u0 = 1.0, u1 = 0.0;
      return;
    }
    double t0 = (lo - a) / d, t1 = (hi - a) / d;
    if (t0 > t1) std::swap(t0, t1);
    u0 = std::max(u0, t0);
    u1 = std::min(u1, t1);
  };
  slab(ax, t.cross_x, g.origin_x_m, g.origin_x_m + g.cols * g.dx_m);
  slab(ay, t.cross_y, g.origin_y_m - g.rows * g.dy_m, g.origin_y_m);
  return {u0, u1};
}

// The terrain along one zero-Doppler line: samples (u, h) every `step`
// over its part in the scene, h the cell's elevation (h_ref off data).
struct LineProfile {
  std::vector<double> u, h;
};

LineProfile sample_line(const Scene& g, const Track& t, double s, const CellElevation& elevation,
                        double h_ref) {
  LineProfile p;
  const auto [u0, u1] = line_in_scene(g, t, s);
  if (!(u0 <= u1)) return p;
  const double step = 0.5 * std::min(g.dx_m, g.dy_m);
  const auto n = static_cast<std::int64_t>(std::floor((u1 - u0) / step));
  int last_row = -1, last_col = -1;
  double last_h = h_ref;
  for (std::int64_t k = 0; k <= n; ++k) {
    const double u = u0 + static_cast<double>(k) * step;
    const auto [x, y] = t.world_from_along_cross(s, u);
    const auto [fc, fr] = g.grid_from_world(x, y);
    const int col = std::clamp(static_cast<int>(std::floor(fc)), 0, g.cols - 1);
    const int row = std::clamp(static_cast<int>(std::floor(fr)), 0, g.rows - 1);
    if (row != last_row || col != last_col) {  // one read a cell
      const float z = elevation(row, col);
      last_h = std::isfinite(z) ? double(z) : h_ref;
      last_row = row;
      last_col = col;
    }
    p.u.push_back(u);
    p.h.push_back(last_h);
  }
  return p;
}

// The ground point (u, h) of slant range R on the line: the first crossing
// of R along the profile, else flat terrain at h_ref; none when R is shorter
// than the height above h_ref.
std::optional<std::pair<double, double>> ground_point(const LineProfile& p, double altitude_m,
                                                      double R, double h_ref) {
  const auto range = [&](std::size_t k) {
    const double dz = altitude_m - p.h[k];
    return std::sqrt(p.u[k] * p.u[k] + dz * dz);
  };
  const double dz_ref = altitude_m - h_ref;
  const double u_flat = R >= std::abs(dz_ref) ? std::sqrt(R * R - dz_ref * dz_ref) : -1.0;
  if (!p.u.empty() && !(u_flat >= 0.0 && u_flat < p.u.front())) {
    double r0 = range(0);
    for (std::size_t k = 0; k + 1 < p.u.size(); ++k) {
      const double r1 = range(k + 1);
      if ((r0 - R) * (r1 - R) <= 0.0 && r0 != r1) {
        const double f = (R - r0) / (r1 - r0);
        return std::pair{p.u[k] + f * (p.u[k + 1] - p.u[k]), p.h[k] + f * (p.h[k + 1] - p.h[k])};
      }
      r0 = r1;
    }
  }
  if (u_flat < 0.0) return std::nullopt;
  return std::pair{u_flat, h_ref};
}

// n positions from 0 to extent, both included (one when extent is 0).
std::vector<double> spread(int extent, int per_side) {
  const int n = std::max(1, std::min(per_side, extent + 1));
  std::vector<double> v(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < n; ++i)
    v[static_cast<std::size_t>(i)] = n == 1 ? 0.0 : double(extent) * i / (n - 1);
  return v;
}

}  // namespace

std::vector<TiePoint> slant_tie_points(const Scene& grid, const Track& track,
                                       const SlantGridLayout& layout,
                                       const CellElevation& elevation, double reference_height_m,
                                       int per_side) {
  RIS_CHECK(layout.line_spacing_m > 0.0 && layout.range_bin_m > 0.0 && per_side >= 2);
  std::vector<TiePoint> out;
  for (const double line : spread(layout.lines, per_side)) {
    const double s = line * layout.line_spacing_m;
    const LineProfile p = sample_line(grid, track, s, elevation, reference_height_m);
    for (const double pixel : spread(layout.bins, per_side)) {
      const double R = layout.near_range_m + pixel * layout.range_bin_m;
      const auto g = ground_point(p, track.altitude_m, R, reference_height_m);
      if (!g) continue;
      const auto [x, y] = track.world_from_along_cross(s, g->first);
      out.push_back({pixel, line, x, y, g->second});
    }
  }
  return out;
}

}  // namespace ris
