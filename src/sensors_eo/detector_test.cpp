#include "ris/sensors_eo/detector.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ris {
namespace {

// Poisson: mean and variance equal, for small means (Knuth) and large ones
// (normal approximation), within 4 standard errors of 20000 draws.
TEST(Detector, PoissonMeanEqualsVariance) {
  for (double mean : {0.7, 5.0, 29.0, 31.0, 400.0}) {
    const int n = 20000;
    double s = 0, s2 = 0;
    for (int i = 0; i < n; ++i) {
      CounterRng rng(7, static_cast<std::uint32_t>(i), 0, 1);
      const double k = poisson_electrons(mean, rng);
      EXPECT_EQ(k, std::floor(k));
      s += k;
      s2 += k * k;
    }
    const double m = s / n, var = s2 / n - m * m;
    EXPECT_NEAR(m, mean, 4.0 * std::sqrt(mean / n)) << mean;
    // The variance of a sample variance of a Poisson law: (mean + 2 mean^2) / n.
    EXPECT_NEAR(var, mean, 4.0 * std::sqrt((mean + 2 * mean * mean) / n)) << mean;
  }
}

// The photon transfer curve: DN variance = (shot + read^2) x gain^2, the
// mean DN = N x gain (gain = (2^bits - 1) / full well), and a radiance over
// the full well saturates at 2^bits - 1.
TEST(Detector, DigitalNumberFollowsThePhotonTransferModel) {
  const Detector d{100.0, 20.0, 40950.0, 12};  // gain 0.1 DN per electron
  const double radiance = 50.0;                // 5000 electrons
  const int n = 20000;
  double s = 0, s2 = 0;
  for (int i = 0; i < n; ++i) {
    CounterRng rng(3, static_cast<std::uint32_t>(i), 0, 2);
    const double dn = digital_number(d, radiance, rng);
    s += dn;
    s2 += dn * dn;
  }
  const double m = s / n, var = s2 / n - m * m;
  EXPECT_NEAR(m, 500.0, 4.0 * std::sqrt(54.0 / n));
  const double expected_var = (5000.0 + 400.0) * 0.01 + 1.0 / 12.0;  // + quantisation
  EXPECT_NEAR(var, expected_var, 4.0 * expected_var * std::sqrt(2.0 / n));
  CounterRng rng(3, 0, 0, 3);
  EXPECT_EQ(digital_number(d, 1e6, rng), 4095);
  EXPECT_EQ(digital_number(Detector{100.0, 0.0, 40950.0, 12}, 0.0, rng), 0);
}

}  // namespace
}  // namespace ris
