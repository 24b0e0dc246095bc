// The azimuth integrator's kernels: each vector version (AVX2, AVX-512:
// skipped on a CPU without it) against the scalar rule, byte for byte.
#include "kernels/image/azimuth_kernels.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include "kernels/simd/cpu.h"
#include "ris/image/slar_image.h"

namespace ris::kernels {
namespace {

// Running sums of `lines` random profile rows of `bins` (rows 0..lines).
struct Sums {
  int lines, bins;
  std::vector<double> cum, cum_area, half;
  std::vector<int> data, visible, layover;
  Sums(int lines_, int bins_, std::mt19937& rng) : lines(lines_), bins(bins_) {
    const std::size_t n = static_cast<std::size_t>(lines + 1) * static_cast<std::size_t>(bins);
    cum.assign(n, 0.0);
    cum_area.assign(n, 0.0);
    data.assign(n, 0);
    visible.assign(n, 0);
    layover.assign(n, 0);
    std::vector<std::uint8_t> touch(static_cast<std::size_t>(bins));
    std::vector<float> power(touch.size()), area(touch.size());
    for (int j = 0; j < lines; ++j) {
      for (std::size_t b = 0; b < touch.size(); ++b) {
        touch[b] = static_cast<std::uint8_t>(rng() % 8);
        power[b] = (touch[b] & slar_touch::kData) ? static_cast<float>(rng() % 1000) * 1e-9f : 0.0f;
        area[b] = (touch[b] & slar_touch::kData) ? static_cast<float>(rng() % 500) : 0.0f;
      }
      const CumRow prev = row(j), next = row(j + 1);
      push_row(bins, touch.data(), power.data(), area.data(), prev, next);
    }
    // Footprints from under a line to many lines, growing with the bin.
    half.resize(static_cast<std::size_t>(bins));
    for (int b = 0; b < bins; ++b) half[static_cast<std::size_t>(b)] = 0.3 + 0.11 * b;
  }
  CumRow row(int j) {
    const std::size_t at = static_cast<std::size_t>(j) * static_cast<std::size_t>(bins);
    return {cum.data() + at, cum_area.data() + at, data.data() + at, visible.data() + at,
            layover.data() + at};
  }
  EmitRows emit_rows() const {
    return {cum.data(),     cum_area.data(), data.data(), visible.data(),
            layover.data(), half.data(),     0,           bins,
            lines};
  }
};

// Every line's pixels [3, bins - 2) by the given code against the scalar rule.
void expect_scalar_bytes(bool avx2, bool avx512) {
  std::mt19937 rng(17);
  const Sums s(40, 61, rng);
  const EmitRows r = s.emit_rows();
  const std::size_t n = static_cast<std::size_t>(s.bins);
  for (int k = 0; k < s.lines; ++k) {
    std::vector<float> p_v(n, -1.0f), a_v(n, -1.0f), p_s(n, -1.0f), a_s(n, -1.0f);
    std::vector<std::uint8_t> m_v(n, 0xee), m_s(n, 0xee);
    emit_line(r, k, 3, s.bins - 2, p_v.data(), a_v.data(), m_v.data(), avx2, avx512);
    emit_line(r, k, 3, s.bins - 2, p_s.data(), a_s.data(), m_s.data(), false, false);
    ASSERT_EQ(std::memcmp(p_v.data(), p_s.data(), n * sizeof(float)), 0) << "line " << k;
    ASSERT_EQ(std::memcmp(a_v.data(), a_s.data(), n * sizeof(float)), 0) << "line " << k;
    ASSERT_EQ(std::memcmp(m_v.data(), m_s.data(), n), 0) << "line " << k;
  }
}

TEST(AzimuthKernels, EmitLineAvx2GivesTheScalarBytes) {
  if (!cpu_has_avx2()) GTEST_SKIP() << "this CPU has no AVX2";
  expect_scalar_bytes(true, false);
}

TEST(AzimuthKernels, EmitLineAvx512GivesTheScalarBytes) {
  if (!cpu_has_avx512()) GTEST_SKIP() << "this CPU has no AVX-512 (F, VL, BW, DQ)";
  expect_scalar_bytes(true, true);
}

TEST(AzimuthKernels, PushRowVectorGivesTheScalarBytes) {
  RecordProperty("clone", cpu_has_avx2() ? "avx2" : "baseline");
  std::mt19937 rng(23);
  const int bins = 77;
  Sums a(1, bins, rng), b(1, bins, rng);  // row 0 of each: zeros; row 1: the push under test
  std::vector<std::uint8_t> touch(static_cast<std::size_t>(bins));
  std::vector<float> power(touch.size()), area(touch.size());
  for (std::size_t i = 0; i < touch.size(); ++i) {
    touch[i] = static_cast<std::uint8_t>(rng() % 8);
    power[i] = static_cast<float>(rng() % 977) * 1e-7f;
    area[i] = static_cast<float>(rng() % 311);
  }
  push_row(bins, touch.data(), power.data(), area.data(), a.row(0), a.row(1));
  push_row_scalar(bins, touch.data(), power.data(), area.data(), b.row(0), b.row(1));
  EXPECT_EQ(std::memcmp(a.cum.data(), b.cum.data(), a.cum.size() * sizeof(double)), 0);
  EXPECT_EQ(std::memcmp(a.cum_area.data(), b.cum_area.data(), a.cum.size() * sizeof(double)), 0);
  EXPECT_EQ(a.data, b.data);
  EXPECT_EQ(a.visible, b.visible);
  EXPECT_EQ(a.layover, b.layover);
}

}  // namespace
}  // namespace ris::kernels
