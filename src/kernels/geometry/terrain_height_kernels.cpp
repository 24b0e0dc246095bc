#include "kernels/geometry/terrain_height_kernels.h"

#include "ris/kernels/vector_clones.h"

namespace ris::kernels {

// Eight floats at a time in the AVX2 clone.
RIS_VECTOR_CLONES bool any_at_or_above(std::size_t n, const std::uint8_t* __restrict valid,
                                       const float* __restrict h, float threshold) {
  int reaches = 0;
  for (std::size_t i = 0; i < n; ++i) reaches |= (valid[i] != 0) & (h[i] >= threshold);
  return reaches != 0;
}

}  // namespace ris::kernels
