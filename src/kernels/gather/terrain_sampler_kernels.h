// Kernels of the line sampler (ris/geometry/terrain_line.h): a row of
// texels, and a span of a line's samples. Each runs its AVX-512 kernel
// (hand-written intrinsics, kernels/simd/avx512.h) when `wide`, else its
// portable code (AVX2 / baseline clones of GCC-vectorised loops): both give
// the same bytes (kernels/gather/terrain_sampler_kernels_test.cpp).
#pragma once

#include <cstdint>

#include "ris/geometry/terrain_line.h"

namespace ris::kernels {

// One scene row's interior texels (columns [1, cols - 1)): z, v, cat the
// row, zs / vs and zn / vn the rows south (r + 1) and north (r - 1) or a
// row without data beyond the scene's edge. The edge columns are the
// caller's.
void texel_row(bool wide, int cols, double dx_m, double dy_m, const float* z, const std::uint8_t* v,
               const std::uint16_t* cat, const float* zs, const std::uint8_t* vs, const float* zn,
               const std::uint8_t* vn, TerrainTexel* out);

// Samples [begin, end) of `line` (all inside the scene) from the texels of
// a rows x cols scene (4 floats a cell) into out[j - begin].
void sample_span(bool wide, const float* tex, int rows, int cols, const GridLine& line, int begin,
                 int end, const SampledTerrain& out);

}  // namespace ris::kernels
