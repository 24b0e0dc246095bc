// Internal: a band of scene rows [r0, r0 + rows) with a float and a byte per
// cell, as a rank computes it and rank 0 writes it: the block of the passes
// over scene rows (a track off the axes' scene maps: incidence and mask;
// geocoding: power and greytone). Its bytes on the wire are the header
// (r0, rows), the floats, then the bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace ris::detail {

struct RowBand {
  int r0 = 0, rows = 0;
  std::vector<float> values;
  std::vector<std::uint8_t> bytes;
};

void pack_row_band(const RowBand& k, std::vector<char>& out);
// pack_row_band's inverse, for rows of `cols` cells.
RowBand unpack_row_band(const char* p, std::size_t n, int cols);

}  // namespace ris::detail
