// Timing helpers of `ris bench`'s sections (bench_camera.cpp,
// bench_quad_pol.cpp): the median of repeated runs and seconds since a
// steady-clock time point.
#pragma once

#include <algorithm>
#include <chrono>
#include <vector>

namespace ris::app {

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace ris::app
