#include "ris/geometry/terrain_line.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <tuple>

#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"

namespace ris {

TerrainTexels terrain_texels(const Scene& scene) {
  TerrainTexels t;
  t.rows = scene.rows;
  t.cols = scene.cols;
  t.texel.resize(scene.size());
  const float nan = std::numeric_limits<float>::quiet_NaN();
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      const std::size_t i = scene.index(r, c);
      TerrainTexel& x = t.texel[i];
      x.category = static_cast<float>(scene.category[i]);
      if (!scene.valid[i]) {
        x.height_m = x.dz_dx = x.dz_dy = nan;
        continue;
      }
      x.height_m = scene.elevation_m[i];
      const auto [gx, gy] = cell_slope(scene, r, c);
      x.dz_dx = gx;
      x.dz_dy = gy;
    }
  }
  return t;
}

GridLine grid_line(const Scene& scene, double x0_m, double y0_m, double dir_x, double dir_y,
                   double first_u_m, double step_m) {
  GridLine l;
  std::tie(l.col0, l.row0) =
      scene.grid_from_world(x0_m + first_u_m * dir_x, y0_m + first_u_m * dir_y);
  // Rows grow southwards (-y).
  l.dcol = step_m * dir_x / scene.dx_m;
  l.drow = -step_m * dir_y / scene.dy_m;
  return l;
}

namespace {

// The first j in [0, n) where a predicate that is false and then true
// holds (n when none), by bisection.
template <typename Pred>
int first_true(int n, Pred pred) {
  int lo = 0, hi = n;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (pred(mid))
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

}  // namespace

std::pair<int, int> inside_samples(const GridLine& line, int rows, int cols, int samples) {
  // Each coordinate a(j) = a0 + j da is monotone in j in floating point too
  // (each rounding is), so each of the four bounds 0 <= a(j) <= n holds on a
  // prefix or a suffix of the samples: bisect for its end. Exact, whatever
  // the rounding of an analytic intersection would be (a line along an edge,
  // a step of 1e-17 cells), in about 4 log2(samples) evaluations.
  int begin = 0, end = samples;
  const auto bound = [&](auto a, double da, double n) {
    const auto ge0 = [&](int j) { return a(j) >= 0.0; };
    const auto le_n = [&](int j) { return a(j) <= n; };
    if (da > 0.0) {
      begin = std::max(begin, first_true(samples, ge0));
      end = std::min(end, first_true(samples, [&](int j) { return !le_n(j); }));
    } else if (da < 0.0) {
      begin = std::max(begin, first_true(samples, le_n));
      end = std::min(end, first_true(samples, [&](int j) { return !ge0(j); }));
    } else if (!(ge0(0) && le_n(0))) {
      end = 0;  // along this axis, outside (or NaN)
    }
  };
  bound([&](int j) { return line.col(j); }, line.dcol, cols);
  bound([&](int j) { return line.row(j); }, line.drow, rows);
  if (begin >= end) return {0, 0};
  return {begin, end};
}

namespace {

// Four floats as one SSE register (GCC/Clang vector extension; SSE2 is the
// x86-64 baseline, so no CPU dispatch and the same bytes everywhere).
using Float4 = float __attribute__((vector_size(16)));

inline Float4 load_texel(const TerrainTexel& t) {
  Float4 v;
  std::memcpy(&v, &t, sizeof v);
  return v;
}

}  // namespace

void sample_terrain_line(const TerrainTexels& tex, const GridLine& line, int begin, int end,
                         const SampledTerrain& out) {
  const TerrainTexel* texel = tex.texel.data();
  for (int j = begin; j < end; ++j) {
    const BilinearFootprint fp = bilinear_footprint(tex.rows, tex.cols, line.col(j), line.row(j));
    // Sum of weight x (height, dz/dx, dz/dy, -) over the corners with a
    // weight above 0, in corner order (as bilinear_terrain_sample): a
    // no-data corner's NaN makes the sample no data.
    Float4 acc = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int k = 0; k < 4; ++k) {
      if (fp.weight[k] > 0.0f) acc += load_texel(texel[fp.index[k]]) * fp.weight[k];
    }
    const auto o = static_cast<std::size_t>(j - begin);
    const bool no_data = std::isnan(acc[0]);
    out.height_m[o] = acc[0];
    out.dz_dx[o] = acc[1];
    out.dz_dy[o] = acc[2];
    out.category[o] = no_data ? std::uint16_t{0}
                              : static_cast<std::uint16_t>(texel[fp.index[fp.nearest]].category);
    out.flags[o] = no_data ? sample_flag::kNoData : std::uint8_t{0};
  }
}

}  // namespace ris
