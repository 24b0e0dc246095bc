// Internal: a window of a streamed scene with its texels
// (ris/geometry/terrain_line.h), and the line sampler run on it in the whole
// scene's grid coordinates, so that every sample takes the in-memory cells,
// weights and bytes. Shared by the streamed PPI (ppi_stream.cpp) and the
// streamed oblique SLAR (slar_stream_oblique.cpp).
#pragma once

#include <algorithm>
#include <cstdint>

#include "ris/geometry/terrain_line.h"
#include "ris/scene/scene.h"
#include "ris/scene/scene_stream.h"

namespace ris::detail {

// A rectangle of scene cells, [r0, r1] x [c0, c1] (inclusive; empty when r0 > r1).
struct CellBox {
  int r0 = 1, r1 = 0, c0 = 1, c1 = 0;
  bool empty() const { return r0 > r1 || c0 > c1; }
  std::int64_t cells() const { return empty() ? 0 : std::int64_t(r1 - r0 + 1) * (c1 - c0 + 1); }
  CellBox united(const CellBox& o) const {
    if (empty()) return o;
    if (o.empty()) return *this;
    return {std::min(r0, o.r0), std::max(r1, o.r1), std::min(c0, o.c0), std::max(c1, o.c1)};
  }
};

// The cells sample j's interpolation touches (bilinear_cells on the whole
// scene): its first corner and the next row and column.
CellBox sample_cells(const Scene& grid, const GridLine& line, int j);

// A window of the scene with its texels (ris/geometry/terrain_line.h): the
// texel of every cell that has its four neighbours in the window, or lies on
// the scene's edge, is the whole scene's.
struct TexelWindow {
  int row0 = 0, col0 = 0, rows = 0, cols = 0;
  TerrainTexels tex;
};

// `cells` grown by the one cell each side the slopes read, within the scene.
CellBox padded_box(const CellBox& cells, const Scene& grid);

// The window of `cells` grown by the one cell each side the slopes read
// (within the scene), read from `in` into `scratch` (its buffers reused) and
// its texels made.
TexelWindow read_texel_window(const SceneStreamReader& in, const CellBox& cells, Scene& scratch);

// Samples [j0, j1) of `line` (whole-scene grid coordinates, all inside the
// scene, every cell they touch inside the window) into out[j - j0]: the
// line sampler's arithmetic (kernels/gather/terrain_sampler_kernels.cpp,
// weigh_texels: the corners' weighted texels summed in corner order, a
// corner of weight 0 skipped) on the window's texels.
void sample_from_window(const TexelWindow& w, const Scene& grid, const GridLine& line, int j0,
                        int j1, const SampledTerrain& out);

}  // namespace ris::detail
