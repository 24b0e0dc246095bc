#include "ris/util/fast_math.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace ris {
namespace {

// Float ulps between a and the correctly rounded libm value b.
double ulps(float a, double b) {
  const float bf = static_cast<float>(b);
  const double ulp =
      std::nextafter(std::fabs(bf), std::numeric_limits<float>::infinity()) - std::fabs(bf);
  return std::fabs(double(a) - b) / std::max(ulp, 1e-45);
}

TEST(FastMath, AcosWithinFourUlpsOverMinusOneToOne) {
  double worst = 0.0;
  for (int i = -200000; i <= 200000; ++i) {
    const float x = static_cast<float>(i) / 200000.0f;
    worst = std::max(worst, ulps(fast_acos(x), std::acos(double(x))));
  }
  EXPECT_LT(worst, 4.0);
  EXPECT_EQ(fast_acos(1.0f), 0.0f);
  EXPECT_NEAR(fast_acos(-1.0f), kPiF, 1e-6f);
  EXPECT_TRUE(std::isnan(fast_acos(std::numeric_limits<float>::quiet_NaN())));
}

TEST(FastMath, AtanWithinFourUlpsOverTheRealLine) {
  double worst = 0.0;
  for (int i = -200000; i <= 200000; ++i) {
    // Dense near 0, out to 1e4 (look angles from 0 to 89.99 deg and beyond).
    const double t = i / 200000.0;
    const float x = static_cast<float>(std::copysign(std::pow(10.0, 8.0 * std::fabs(t) - 4.0), t));
    worst = std::max(worst, ulps(fast_atan(x), std::atan(double(x))));
  }
  EXPECT_LT(worst, 4.0);
  EXPECT_EQ(fast_atan(0.0f), 0.0f);
  EXPECT_TRUE(std::isnan(fast_atan(std::numeric_limits<float>::quiet_NaN())));
}

}  // namespace
}  // namespace ris
