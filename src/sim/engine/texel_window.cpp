#include "sim/engine/texel_window.h"

#include <cstddef>

#include "ris/geometry/terrain_sample.h"

namespace ris::detail {

// The cells sample j's interpolation touches (bilinear_cells on the whole
// scene): its first corner and the next row and column.
CellBox sample_cells(const Scene& grid, const GridLine& line, int j) {
  const auto b = bilinear_cells<std::int64_t>(grid.rows, grid.cols, line.col(j), line.row(j));
  const int r = static_cast<int>(b.cell00 / grid.cols), c = static_cast<int>(b.cell00 % grid.cols);
  return {r, r + (b.step_row != 0 ? 1 : 0), c, c + (b.step_col != 0 ? 1 : 0)};
}

CellBox padded_box(const CellBox& c, const Scene& grid) {
  return {std::max(0, c.r0 - 1), std::min(grid.rows - 1, c.r1 + 1), std::max(0, c.c0 - 1),
          std::min(grid.cols - 1, c.c1 + 1)};
}

TexelWindow read_texel_window(const SceneStreamReader& in, const CellBox& cells, Scene& ws) {
  const Scene& grid = in.grid();
  const CellBox w = padded_box(cells, grid);
  TexelWindow tw;
  tw.row0 = w.r0;
  tw.col0 = w.c0;
  tw.rows = w.r1 - w.r0 + 1;
  tw.cols = w.c1 - w.c0 + 1;
  const std::size_t nc = static_cast<std::size_t>(tw.rows) * static_cast<std::size_t>(tw.cols);
  ws.rows = tw.rows;
  ws.cols = tw.cols;
  ws.dx_m = grid.dx_m;
  ws.dy_m = grid.dy_m;
  ws.elevation_m.resize(nc);
  ws.category.resize(nc);
  ws.valid.resize(nc);
  in.read(tw.row0, tw.rows, tw.col0, tw.cols, ws.elevation_m.data(), ws.category.data(),
          ws.valid.data());
  tw.tex = terrain_texels(ws);
  return tw;
}

// Samples [j0, j1) of `line` (whole-scene grid coordinates, all inside the
// scene, every cell they touch inside the window) into out[j - j0]: the
// line sampler's arithmetic (kernels/gather/terrain_sampler_kernels.cpp,
// weigh_texels: the corners' weighted texels summed in corner order, a
// corner of weight 0 skipped) on the window's texels.
void sample_from_window(const TexelWindow& w, const Scene& grid, const GridLine& line, int j0,
                        int j1, const SampledTerrain& out) {
  const auto* t = reinterpret_cast<const float*>(w.tex.texel.get());
  const std::int64_t wcols = w.cols;
  const auto local = [&](std::int64_t cell) {
    const std::int64_t r = cell / grid.cols, c = cell % grid.cols;
    return 4 * ((r - w.row0) * wcols + (c - w.col0));
  };
  for (int j = j0; j < j1; ++j) {
    const auto b = bilinear_cells<std::int64_t>(grid.rows, grid.cols, line.col(j), line.row(j));
    const std::int64_t first = local(b.cell00);
    const std::int64_t d1 = b.step_col != 0 ? 4 : 0, d2 = b.step_row != 0 ? 4 * wcols : 0;
    const std::int64_t corner[4] = {first, first + d1, first + d2, first + d2 + d1};
    float acc[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int k = 0; k < 4; ++k) {
      const float wk = b.weight[k];
      if (!(wk > 0.0f)) continue;
      const float* p = t + corner[k];
      for (int q = 0; q < 4; ++q) acc[q] += wk * p[q];
    }
    const float h = acc[0];
    const bool no_data = h != h;
    const auto o = static_cast<std::size_t>(j - j0);
    out.height_m[o] = h;
    out.dz_dx[o] = acc[1];
    out.dz_dy[o] = acc[2];
    out.category[o] = no_data
                          ? std::uint16_t{0}
                          : static_cast<std::uint16_t>(static_cast<int>(t[local(b.nearest) + 3]));
    out.flags[o] = no_data ? sample_flag::kNoData : std::uint8_t{0};
  }
}

}  // namespace ris::detail
