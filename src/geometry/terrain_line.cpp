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

std::pair<int, int> inside_samples(const GridLine& line, int rows, int cols, int samples) {
  // The line-rectangle intersection in j, per axis: 0 <= a0 + j da <= n.
  double lo = 0.0, hi = samples;
  const auto clip = [&](double a0, double da, double n) {
    if (da > 0.0) {
      lo = std::max(lo, -a0 / da);
      hi = std::min(hi, (n - a0) / da);
    } else if (da < 0.0) {
      lo = std::max(lo, (n - a0) / da);
      hi = std::min(hi, -a0 / da);
    } else if (!(a0 >= 0.0 && a0 <= n)) {
      hi = -1.0;  // parallel to this axis and outside
    }
  };
  clip(line.col0, line.dcol, cols);
  clip(line.row0, line.drow, rows);
  if (!(lo <= hi)) return {0, 0};
  // Rounding moves the ends by far less than a sample: widen by two and
  // check exactly, walking in from both ends (inside() is one interval).
  const int a = static_cast<int>(std::clamp(std::floor(lo) - 2.0, 0.0, double(samples)));
  const int b = static_cast<int>(std::clamp(std::ceil(hi) + 3.0, 0.0, double(samples)));
  int begin = a;
  while (begin < b && !line.inside(begin, rows, cols)) ++begin;
  int end = b;
  while (end > begin && !line.inside(end - 1, rows, cols)) --end;
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
