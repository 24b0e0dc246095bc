// The line sampler's AVX-512 kernels (skipped on a CPU without AVX-512)
// against its portable code, byte for byte.
#include "kernels/gather/terrain_sampler_kernels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "kernels/simd/cpu.h"

namespace ris::kernels {
namespace {

struct Grid {
  int rows, cols;
  std::vector<float> z;
  std::vector<std::uint8_t> v;
  std::vector<std::uint16_t> cat;
  Grid(int rows_, int cols_, std::mt19937& rng) : rows(rows_), cols(cols_) {
    const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
    z.resize(n);
    v.resize(n);
    cat.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      z[i] = static_cast<float>(std::sin(0.37 * double(i)) * 80.0 + double(rng() % 100) * 0.1);
      v[i] = rng() % 9 == 0 ? 0 : 1;
      cat[i] = static_cast<std::uint16_t>(rng() % 12);
    }
  }
  // Row r's interior texels by one kernel (the edge columns are left 0).
  std::vector<TerrainTexel> texels(bool wide) const {
    std::vector<TerrainTexel> t(z.size(), TerrainTexel{0, 0, 0, 0});
    const std::vector<float> no_z(static_cast<std::size_t>(cols), 0.0f);
    const std::vector<std::uint8_t> no_v(static_cast<std::size_t>(cols), 0);
    for (int r = 0; r < rows; ++r) {
      const std::size_t at = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols);
      const std::size_t c = static_cast<std::size_t>(cols);
      const bool south = r + 1 < rows, north = r > 0;
      texel_row(wide, cols, 6.0, 7.0, &z[at], &v[at], &cat[at], south ? &z[at + c] : no_z.data(),
                south ? &v[at + c] : no_v.data(), north ? &z[at - c] : no_z.data(),
                north ? &v[at - c] : no_v.data(), &t[at]);
    }
    return t;
  }
};

TEST(TerrainSamplerKernels, Avx512TexelsAndSamplesGiveThePortableBytes) {
  if (!cpu_has_avx512()) GTEST_SKIP() << "this CPU has no AVX-512 (F, VL, BW, DQ)";
  std::mt19937 rng(29);
  const Grid g(37, 53, rng);
  const std::vector<TerrainTexel> wide = g.texels(true), portable = g.texels(false);
  ASSERT_EQ(std::memcmp(wide.data(), portable.data(), wide.size() * sizeof(TerrainTexel)), 0);

  // Lines at several headings across the grid, every sample inside it.
  const auto* tex = reinterpret_cast<const float*>(portable.data());
  for (const double deg : {3.0, 30.0, 45.0, 71.0, 137.0}) {
    const double a = deg * M_PI / 180.0;
    GridLine line{26.5 - 15.0 * std::cos(a), 18.5 - 15.0 * std::sin(a), 0.07 * std::cos(a),
                  0.07 * std::sin(a)};
    const int n = 429;  // ~30 cells: more than two of the sampler's chunks
    std::vector<float> h[2], gx[2], gy[2];
    std::vector<std::uint16_t> c[2];
    std::vector<std::uint8_t> f[2];
    for (int k = 0; k < 2; ++k) {
      h[k].assign(n, -1.0f);
      gx[k] = gy[k] = h[k];
      c[k].assign(n, 7);
      f[k].assign(n, 7);
      sample_span(k == 0, tex, g.rows, g.cols, line, 0, n,
                  {h[k].data(), gx[k].data(), gy[k].data(), c[k].data(), f[k].data()});
    }
    EXPECT_EQ(std::memcmp(h[0].data(), h[1].data(), n * sizeof(float)), 0) << deg;
    EXPECT_EQ(std::memcmp(gx[0].data(), gx[1].data(), n * sizeof(float)), 0) << deg;
    EXPECT_EQ(std::memcmp(gy[0].data(), gy[1].data(), n * sizeof(float)), 0) << deg;
    EXPECT_EQ(c[0], c[1]) << deg;
    EXPECT_EQ(f[0], f[1]) << deg;
  }
}

}  // namespace
}  // namespace ris::kernels
