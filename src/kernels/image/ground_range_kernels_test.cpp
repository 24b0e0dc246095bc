// The ground-range kernels' AVX2 versions (skipped on a CPU without AVX2)
// against their scalar loops, byte for byte.
#include "kernels/image/ground_range_kernels.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "kernels/simd/cpu.h"

namespace ris::kernels {
namespace {

TEST(GroundRangeKernels, Avx2ResampleAndNearestGiveTheScalarBytes) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2";
  std::mt19937 rng(31);
  const int bins = 300;
  std::vector<float> slant(bins);
  std::vector<std::uint8_t> mask(bins);
  for (int b = 0; b < bins; ++b) {
    slant[static_cast<std::size_t>(b)] = static_cast<float>(rng() % 100000) * 1e-9f;
    mask[static_cast<std::size_t>(b)] = static_cast<std::uint8_t>(rng() % 8);
  }
  // Ground columns over the bins, a few per bin near range and fewer far
  // out (as the ground-range grid: its columns are finer than the bins'
  // footprints), and a stretch of one column a bin (blocks that do not fit
  // a register).
  std::vector<std::int32_t> k0, k1, nearest;
  std::vector<double> w;
  double x = 0.0;
  while (x < bins - 1.0) {
    const auto k = static_cast<std::int32_t>(x);
    k0.push_back(k);
    k1.push_back(k + 1);
    w.push_back(x - k);
    nearest.push_back(x - k < 0.5 ? k : k + 1);
    x += x < 150.0 ? 0.17 + 0.002 * x : 1.3;
  }
  const std::size_t n = w.size();
  for (const auto& [begin, end] : {std::pair<std::size_t, std::size_t>{0, n}, {3, n - 5}}) {
    std::vector<float> out_v(n, -1.0f), out_s(n, -1.0f);
    resample_columns(true, slant.data(), bins, k0.data(), k1.data(), w.data(), begin, end,
                     out_v.data());
    resample_columns(false, slant.data(), bins, k0.data(), k1.data(), w.data(), begin, end,
                     out_s.data());
    EXPECT_EQ(std::memcmp(out_v.data(), out_s.data(), n * sizeof(float)), 0) << begin;
    std::vector<std::uint8_t> m_v(n, 0xee), m_s(n, 0xee);
    nearest_columns(true, mask.data(), bins, nearest.data(), begin, end, m_v.data());
    nearest_columns(false, mask.data(), bins, nearest.data(), begin, end, m_s.data());
    EXPECT_EQ(m_v, m_s) << begin;
  }
}

}  // namespace
}  // namespace ris::kernels
