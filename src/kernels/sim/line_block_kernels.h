// Kernels of the fused line engine along a grid axis (ris/sim/
// slar_line_blocks.h): a row of scene cells into a line's terrain, a line's
// scene-grid maps back into a row, and the 8 x 8 transposes of the column
// tile. Each vector kernel (util's 8-lane GCC vector types, kernels/simd/
// vec8.h, in AVX-512 / AVX2 / baseline clones) has a portable scalar twin
// (`_scalar`) doing the same operations one cell at a time: both give the
// same bytes (kernels/sim/line_block_kernels_test.cpp).
//
// Example:
//   ris::kernels::gather_row(row, scene.dx_m, scene.dy_m, /*reverse=*/false, out);
#pragma once

#include <cstddef>
#include <cstdint>

namespace ris::kernels {

// The transposes' block: 8 x 8 cells.
inline constexpr int kTileLanes = 8;

// A row of `cols` scene cells and its two neighbour rows (a row of no-data
// cells beyond the scene's edge): elevation, validity (0: no data) and
// category. North (+y) is row r - 1.
struct CellRow {
  int cols = 0;
  const float* z = nullptr;
  const std::uint8_t* valid = nullptr;
  const std::uint16_t* category = nullptr;
  const float* z_north = nullptr;
  const std::uint8_t* valid_north = nullptr;
  const float* z_south = nullptr;
  const std::uint8_t* valid_south = nullptr;
};

// A line's terrain, `cols` samples each, in sample order. unseen: the
// sample_flag::kUnseen bits of each sample (or'ed into flags).
struct LineTerrainOut {
  float* height_m = nullptr;  // NaN where no data
  float* dz_dx = nullptr;     // NaN where no data
  float* dz_dy = nullptr;     // NaN where no data
  std::uint16_t* category = nullptr;
  std::uint8_t* flags = nullptr;  // sample_flag::kNoData | unseen
  const std::uint8_t* unseen = nullptr;
};

// The cells of `row` into `out` in sample order (column c is sample c, or
// cols - 1 - c with `reverse`): height, slope (slope_difference, as
// surface_gradient: dx_m and dy_m the cell steps), category, flags.
void gather_row(const CellRow& row, double dx_m, double dy_m, bool reverse,
                const LineTerrainOut& out);
void gather_row_scalar(const CellRow& row, double dx_m, double dy_m, bool reverse,
                       const LineTerrainOut& out);

// The scene-grid maps (scene_map_cell) of a line whose sample j is cell j of
// a row, or n - 1 - j (`reverse`): mask and local incidence in degrees.
void map_row(int n, bool reverse, double near_m, double far_m, const std::uint8_t* flags,
             const float* range, const float* local_incidence, const std::uint8_t* valid,
             std::uint8_t* mask, float* deg);
void map_row_scalar(int n, bool reverse, double near_m, double far_m, const std::uint8_t* flags,
                    const float* range, const float* local_incidence, const std::uint8_t* valid,
                    std::uint8_t* mask, float* deg);

// The column tile's transposes: scene cell (r, c) of rows [0, rows8) and
// columns [0, cols8) (multiples of 8) is src + r * stride + c; its tile entry
// is (tile_rows - 1 - c) * len + len - 1 - r.
void transpose_into_tile(int rows8, int cols8, int tile_rows, std::size_t len, std::size_t stride,
                         const float* z, const std::uint16_t* cat, const std::uint8_t* v, float* tz,
                         std::uint16_t* tcat, std::uint8_t* tv);
void transpose_into_tile_scalar(int rows8, int cols8, int tile_rows, std::size_t len,
                                std::size_t stride, const float* z, const std::uint16_t* cat,
                                const std::uint8_t* v, float* tz, std::uint16_t* tcat,
                                std::uint8_t* tv);
// The inverse for the scene maps: tile entry (tile_rows - 1 - c) * len +
// len - 1 - r into dst + r * stride + c.
void transpose_from_tile(int rows8, int cols8, int tile_rows, std::size_t len, std::size_t stride,
                         const std::uint8_t* tmask, const float* tdeg, std::uint8_t* mask,
                         float* deg);
void transpose_from_tile_scalar(int rows8, int cols8, int tile_rows, std::size_t len,
                                std::size_t stride, const std::uint8_t* tmask, const float* tdeg,
                                std::uint8_t* mask, float* deg);

}  // namespace ris::kernels
