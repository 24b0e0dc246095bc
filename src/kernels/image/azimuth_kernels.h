// Kernels of the azimuth integrator (ris/image/slar_azimuth_integrator.h):
// a line's profile added to the running sums, and a line of pixels
// integrated from them. AVX2 / AVX-512 versions (clones and intrinsics)
// beside scalar ones, the same bytes (kernels/image/azimuth_kernels_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>

namespace ris::kernels {

// One running-sum row: its five arrays.
struct CumRow {
  double* power;
  double* area;
  int* data;
  int* visible;
  int* layover;
};

// Running-sum row next = prev + a line's profile (touch bits, power,
// area) over n bins; returns the bins [lo, hi) outside which the profile's
// touch, power and area are all zero ({0, 0} when all are).
std::pair<int, int> push_row(int n, const std::uint8_t* touch, const float* power,
                             const float* area, const CumRow& prev, const CumRow& next);
// The running-sum update alone, one bin at a time (push_row's twin).
void push_row_scalar(int n, const std::uint8_t* touch, const float* power, const float* area,
                     const CumRow& prev, const CumRow& next);

// What a line of pixels reads: the running sums (rows of `bins`, the first
// kept one being running-sum index `base`), the footprint's half length per
// bin and the image's line count.
struct EmitRows {
  const double* cum;
  const double* cum_area;
  const int* cum_data;
  const int* cum_visible;
  const int* cum_layover;
  const double* half;
  int base;
  int bins;
  int lines;
  std::size_t row(int cum_index) const {
    return static_cast<std::size_t>(cum_index - base) * static_cast<std::size_t>(bins);
  }
};

// Pixels [begin, end) of line k: the profile integrated over the footprint
// and the mask. avx2 / avx512: which vector code may run (false: the scalar
// rule for every pixel; the same bytes).
void emit_line(const EmitRows& r, int k, int begin, int end, float* power, float* area,
               std::uint8_t* mask, bool avx2, bool avx512);

}  // namespace ris::kernels
