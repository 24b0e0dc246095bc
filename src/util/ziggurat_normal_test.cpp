#include "ris/util/ziggurat_normal.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace ris {
namespace {

double normal_cdf(double x) {
  return 0.5 * std::erfc(-x / std::sqrt(2.0));
}

// 2 x 10^6 draws: moments, the CDF at points across the body, the wedges and
// the tail (beyond R = 3.44), within 5 standard errors.
TEST(ZigguratNormal, MomentsAndDistribution) {
  const ZigguratTables& zig = ziggurat_tables();
  constexpr int kN = 2000000;
  const std::vector<double> xs = {-4.0, -3.6, -3.0, -2.0, -1.0, -0.3, 0.0,
                                  0.5,  1.5,  2.5,  3.3,  3.5,  4.0};
  std::vector<int> below(xs.size(), 0);
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
  for (int i = 0; i < kN; ++i) {
    CounterRng rng(11, static_cast<std::uint32_t>(i), 5, CounterRng::kFadingStream);
    const double z = ziggurat_normal(rng, zig);
    s1 += z;
    s2 += z * z;
    s3 += z * z * z;
    s4 += z * z * z * z;
    for (std::size_t k = 0; k < xs.size(); ++k) below[k] += z < xs[k] ? 1 : 0;
  }
  EXPECT_NEAR(s1 / kN, 0.0, 5.0 / std::sqrt(kN));
  EXPECT_NEAR(s2 / kN, 1.0, 5.0 * std::sqrt(2.0 / kN));
  EXPECT_NEAR(s3 / kN, 0.0, 5.0 * std::sqrt(15.0 / kN));
  EXPECT_NEAR(s4 / kN, 3.0, 5.0 * std::sqrt(96.0 / kN));
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const double p = normal_cdf(xs[k]);
    EXPECT_NEAR(double(below[k]) / kN, p, 5.0 * std::sqrt(p * (1 - p) / kN) + 1e-7)
        << "x = " << xs[k];
  }
}

TEST(ZigguratNormal, TablesAreMarsagliaTsangs) {
  const ZigguratTables& t = ziggurat_tables();
  // Layer edges decrease from R to 0; the density at them increases to 1.
  EXPECT_NEAR(t.w[127] * 2147483648.0, ZigguratTables::kR, 1e-12);
  for (int i = 1; i < 127; ++i) {
    EXPECT_LT(t.w[i], t.w[i + 1]) << i;
    EXPECT_GT(t.f[i], t.f[i + 1]) << i;
  }
  EXPECT_EQ(t.f[0], 1.0);
  EXPECT_NEAR(t.f[127], std::exp(-0.5 * ZigguratTables::kR * ZigguratTables::kR), 1e-15);
}

}  // namespace
}  // namespace ris
