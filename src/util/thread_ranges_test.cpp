#include "ris/util/thread_ranges.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <vector>

namespace ris {
namespace {

// The threads' ranges cover [0, n) once each, in order, for any thread count
// (also more threads than elements, and n = 0).
TEST(ThreadRanges, CoverEveryIndexOnce) {
  const int saved = omp_get_max_threads();
  for (int threads : {1, 2, 3}) {
    omp_set_num_threads(threads);
    for (std::size_t n : {0u, 1u, 2u, 5u, 1000u, 1001u}) {
      std::vector<int> hits(n, 0);
      int calls = 0;
      for_thread_ranges(n, [&](std::size_t i0, std::size_t i1) {
        ASSERT_LE(i0, i1);
        ASSERT_LE(i1, n);
        for (std::size_t i = i0; i < i1; ++i) {
#pragma omp atomic
          ++hits[i];
        }
#pragma omp atomic
        ++calls;
      });
      EXPECT_EQ(calls, threads) << n;
      for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(hits[i], 1) << "n " << n << " i " << i;
    }
  }
  omp_set_num_threads(saved);
}

}  // namespace
}  // namespace ris
