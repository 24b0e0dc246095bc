// Kernels of the fading field (ris/image/speckle.h FadingField::apply_line):
// AVX2 intrinsics beside the scalar code, the same bytes (the arithmetic
// in double with separate multiplies and adds in the scalar code's order;
// tested by speckle_test.cpp against the per-pixel draw).
#pragma once

#include <cstdint>

#include "ris/util/ziggurat_normal.h"

namespace ris::kernels {

// Whether fade_quads runs its AVX2 kernel on this CPU.
bool fade_quads_available();

// apply_line's draw in registers, four pixels at a time: writes the pixels
// it decides and returns a bit per pixel (of n <= 64) that the scalar path
// must still draw (all of them where fade_quads_available() is false).
// w0..w2: the pixels' first three counter words; c, d, looks, sqrt_looks:
// per pixel's bin.
std::uint64_t fade_quads(float* row, int n, const std::uint32_t* w0, const std::uint32_t* w1,
                         const std::uint32_t* w2, const ZigguratTables& zig, bool exact,
                         const double* c, const double* d, const double* looks,
                         const double* sqrt_looks);

// Whether any of the n pixels has a positive, finite power (avx2: eight at
// a time).
bool any_to_fade(bool avx2, const float* row, int n);

}  // namespace ris::kernels
