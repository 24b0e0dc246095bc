// Kernels of the ground-range resampler (ris/image/ground_range.h): a
// line's columns interpolated from its slant-range bins, and its mask's
// nearest bins. With `avx2`, eight (sixteen) columns at a time by a
// permutation within a register where their bins fit one; otherwise, and
// for the rest, the scalar loop: the same bytes
// (kernels/image/ground_range_kernels_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

namespace ris::kernels {

// Columns [begin, end): out[j] = a + w[j] (b - a) in double, a = slant[k0[j]],
// b = slant[k1[j]] (bins: the slant line's length).
void resample_columns(bool avx2, const float* slant, int bins, const std::int32_t* k0,
                      const std::int32_t* k1, const double* w, std::size_t begin, std::size_t end,
                      float* out);

// Columns [begin, end): out[j] = slant[nearest[j]].
void nearest_columns(bool avx2, const std::uint8_t* slant, int bins, const std::int32_t* nearest,
                     std::size_t begin, std::size_t end, std::uint8_t* out);

}  // namespace ris::kernels
