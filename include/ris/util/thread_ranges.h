// Runs f(begin, end) once on each OpenMP thread over its equal share of
// [0, n) (one parallel region, no loop scheduling): for a plain scan whose
// loop should compile as it would serially. GCC compiles a loop written
// directly inside `#pragma omp parallel for` into the outlined region, where
// it reads the shared variables through the region's argument block; a byte
// store in the body may alias those, so they are reloaded per element
// (measured: the scene's used-category scan ran 2x slower on one thread that
// way than serially). A function taking the pointers as arguments keeps them
// local, and the loop compiles as the serial one.
//
// Example:
//   std::int64_t total = 0;
//   ris::for_thread_ranges(n, [&](std::size_t i0, std::size_t i1) {
//     const std::int64_t part = count_range(data, i0, i1);  // a plain function
//   #pragma omp atomic
//     total += part;
//   });
#pragma once

#include <omp.h>

#include <cstddef>

namespace ris {

template <typename F>
void for_thread_ranges(std::size_t n, F f) {
#pragma omp parallel
  {
    const auto nt = static_cast<std::size_t>(omp_get_num_threads());
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    // n * t / nt without overflow for any n that fits in memory.
    const std::size_t begin = n / nt * t + n % nt * t / nt;
    const std::size_t end = n / nt * (t + 1) + n % nt * (t + 1) / nt;
    f(begin, end);
  }
}

}  // namespace ris
