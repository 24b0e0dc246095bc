// The oblique scatter kernels' vector clones (the widest this CPU runs)
// against their scalar twins, byte for byte.
#include "kernels/gather/oblique_scatter_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "kernels/simd/cpu.h"
#include "ris/geometry/line_scan.h"

namespace ris::kernels {
namespace {

TEST(ObliqueScatterKernels, ScatterRunVectorGivesTheScalarBytes) {
  RecordProperty("clone", cpu_has_avx2() ? "avx2" : "baseline");
  std::mt19937 rng(5);
  // A block of 16 lines of 40 samples from sample 10, guard columns at 9
  // and 50; the scene row's cells take lines and samples along affine
  // indices that stay within the block.
  const int line0 = 32, lines = 16, lo = 9, hi = 50, width = hi - lo + 1;
  std::vector<std::int32_t> vm(static_cast<std::size_t>(lines * width));
  std::vector<float> vi(vm.size());
  for (std::size_t i = 0; i < vm.size(); ++i) {
    vm[i] = static_cast<std::int32_t>(rng() % 32);
    vi[i] = i % 7 == 0 ? std::nanf("") : static_cast<float>(rng() % 9000) * 0.01f;
  }
  const BlockMapView b{vm.data(), vi.data(), line0, lo, hi, width};
  const int cols = 300;
  std::vector<std::uint8_t> valid(static_cast<std::size_t>(cols));
  for (auto& v : valid) v = rng() % 5 == 0 ? 0 : 1;
  // line = lbase + c line_dc over [line0, line0 + lines); samples beyond
  // the covered range are clamped to the guard columns.
  const double line_dc = 15.0 / 299.0, sample_dc = -45.0 / 299.0;
  for (const auto& [c_begin, c_end] : {std::pair{0, 300}, std::pair{3, 4}, std::pair{17, 270}}) {
    std::vector<std::uint8_t> m_v(valid.size(), 0xee), m_s = m_v;
    std::vector<float> d_v(valid.size(), -1.0f), d_s = d_v;
    scatter_run(line0 + 0.2, line_dc, 52.4, sample_dc, c_begin, c_end, b, valid.data(), m_v.data(),
                d_v.data());
    scatter_run_scalar(line0 + 0.2, line_dc, 52.4, sample_dc, c_begin, c_end, b, valid.data(),
                       m_s.data(), d_s.data());
    EXPECT_EQ(std::memcmp(m_v.data(), m_s.data(), m_v.size()), 0) << c_begin;
    EXPECT_EQ(std::memcmp(d_v.data(), d_s.data(), d_v.size() * sizeof(float)), 0) << c_begin;
  }
}

TEST(ObliqueScatterKernels, MapValuesVectorGivesTheScalarBytes) {
  RecordProperty("clone", cpu_has_avx2() ? "avx2" : "baseline");
  std::mt19937 rng(9);
  const int n = 517;
  std::vector<std::uint8_t> flags(static_cast<std::size_t>(n));
  std::vector<float> range(flags.size()), local(flags.size());
  for (std::size_t j = 0; j < flags.size(); ++j) {
    flags[j] = static_cast<std::uint8_t>(rng() % 32);
    range[j] = j % 17 == 3 ? std::nanf("") : 900.0f + static_cast<float>(rng() % 1200);
    local[j] = static_cast<float>(rng() % 1600) * 1e-3f;
  }
  std::vector<std::int32_t> m_v(flags.size()), m_s(flags.size());
  std::vector<float> d_v(flags.size()), d_s(flags.size());
  map_values(n, flags.data(), range.data(), local.data(), 1000.0, 2000.0, m_v.data(), d_v.data());
  map_values_scalar(n, flags.data(), range.data(), local.data(), 1000.0, 2000.0, m_s.data(),
                    d_s.data());
  EXPECT_EQ(std::memcmp(m_v.data(), m_s.data(), m_v.size() * sizeof(std::int32_t)), 0);
  EXPECT_EQ(std::memcmp(d_v.data(), d_s.data(), d_v.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace ris::kernels
