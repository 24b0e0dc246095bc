// The terrain-below-the-sensor check's scan (ris/geometry/slar_geometry.h
// check_terrain_below_sensor): branch-free, so that it vectorises (AVX2 /
// baseline clones; compares only, the same answer).
#pragma once

#include <cstddef>
#include <cstdint>

namespace ris::kernels {

// Whether a cell with data (valid[i] != 0) has h[i] >= threshold.
bool any_at_or_above(std::size_t n, const std::uint8_t* valid, const float* h, float threshold);

}  // namespace ris::kernels
