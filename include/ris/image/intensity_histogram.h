// Histogram and dynamic range of an intensity image in dB (docs/quality.md):
// the usable pixels' 10 log10(I) in 1 dB bins, their 1st, 50th and 99th
// percentiles and the dynamic range p99 - p1.
#pragma once

#include <cstdint>
#include <vector>

#include "ris/image/speckle_statistics.h"

namespace ris {

struct IntensityHistogram {
  std::int64_t pixels = 0;
  double p1_db = 0.0, p50_db = 0.0, p99_db = 0.0;
  double dynamic_range_db() const { return p99_db - p1_db; }
  double first_bin_db = 0.0;         // lower edge of counts[0]; bins 1 dB wide
  std::vector<std::int64_t> counts;  // at most 300 bins
};

// Throws InputError when no pixel is usable.
IntensityHistogram intensity_histogram(const IntensityView& img);

}  // namespace ris
