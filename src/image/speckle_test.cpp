#include "ris/image/speckle.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "ris/util/units.h"

namespace ris {
namespace {

struct Stats {
  double mean = 0.0;
  double sd = 0.0;
  double below = 0.0;  // fraction of values < threshold
};

Stats stats(const std::vector<float>& v, double scale, double threshold) {
  double s = 0, s2 = 0, below = 0;
  for (float x : v) {
    const double y = x / scale;
    s += y;
    s2 += y * y;
    below += y < threshold ? 1 : 0;
  }
  const double n = static_cast<double>(v.size());
  Stats st;
  st.mean = s / n;
  st.sd = std::sqrt(s2 / n - st.mean * st.mean);
  st.below = below / n;
  return st;
}

// A uniform area of 400 x 500 pixels of mean power p, speckled with N looks.
std::vector<float> speckled_area(double looks, FadingLaw law, double p, std::uint64_t seed) {
  constexpr int kLines = 400, kBins = 500;
  std::vector<float> img(static_cast<size_t>(kLines) * kBins, static_cast<float>(p));
  std::vector<double> n(kBins, looks);
  apply_fading(img, kLines, kBins, n, law, seed);
  return img;
}

Stats area_stats(double looks, FadingLaw law, double p, std::uint64_t seed, double threshold) {
  return stats(speckled_area(looks, law, p, seed), p, threshold);
}

// The test: speckled mean within 2% of the mean power and coefficient
// of variation within 5% of 1/sqrt(N) (exact law), for integer and
// non-integer N, including N < 1 (the boosted branch). With 2e5 pixels the
// standard error of the mean is 0.22% / sqrt(N) and of the CV below 1%.
TEST(Speckle, ExactLawMeanAndCoefficientOfVariation) {
  const double p = 3.5e-12;
  for (double looks : {0.7, 1.0, 3.7, 10.0, 64.0}) {
    const Stats st = area_stats(looks, FadingLaw::exact_gamma, p, 1234, 1.0);
    EXPECT_NEAR(st.mean, 1.0, 0.02) << "N = " << looks;
    EXPECT_NEAR(st.sd / st.mean, 1.0 / std::sqrt(looks), 0.05 / std::sqrt(looks))
        << "N = " << looks;
  }
}

// The shape of the law, not only its moments: P(Y < 1) is the regularised
// lower incomplete gamma P(N, N): 1 - e^-1 = 0.6321 for N = 1 and
// 1 - e^-4 (1 + 4 + 8 + 32/3) = 0.5665 for N = 4.
TEST(Speckle, ExactLawDistribution) {
  EXPECT_NEAR(area_stats(1.0, FadingLaw::exact_gamma, 1.0, 9, 1.0).below, 0.6321, 0.005);
  EXPECT_NEAR(area_stats(4.0, FadingLaw::exact_gamma, 1.0, 9, 1.0).below, 0.5665, 0.005);
}

// Seed form (equation 21 with a floor): mean and sd against the closed forms
// documented in speckle.h, and the fraction of pixels at the floor, Phi(a).
TEST(Speckle, SeedFormStatisticsAsDocumented) {
  const double f = kSeedFadingFloor;
  for (double looks : {1.0, 4.0, 25.0}) {
    const double a = (f - 1.0) * std::sqrt(looks);
    const double big_phi = 0.5 * std::erfc(-a / std::sqrt(2.0));
    const double small_phi = std::exp(-0.5 * a * a) / std::sqrt(2.0 * kPi);
    const double mean = f * big_phi + (1 - big_phi) + small_phi / std::sqrt(looks);
    const double m2 = f * f * big_phi + (1 - big_phi) + 2 * small_phi / std::sqrt(looks) +
                      ((1 - big_phi) + a * small_phi) / looks;
    const double sd = std::sqrt(m2 - mean * mean);
    const Stats st = area_stats(looks, FadingLaw::seed_eq21, 2.0, 77, f * 1.0000001);
    EXPECT_NEAR(st.mean, mean, 0.01 * mean) << "N = " << looks;
    EXPECT_NEAR(st.sd, sd, 0.03 * sd) << "N = " << looks;
    EXPECT_NEAR(st.below, big_phi, 0.005) << "N = " << looks;
  }
  // The documented numbers for N = 1.
  const Stats one = area_stats(1.0, FadingLaw::seed_eq21, 1.0, 5, 0.0);
  EXPECT_NEAR(one.mean, 1.085, 0.01);
  EXPECT_NEAR(one.sd, 0.865, 0.02);
}

// The same seed gives identical bytes with 1 and 2 threads; another seed differs.
TEST(Speckle, SameBytesForAnyThreadCount) {
  const int saved = omp_get_max_threads();
  for (FadingLaw law : {FadingLaw::exact_gamma, FadingLaw::seed_eq21}) {
    omp_set_num_threads(1);
    const std::vector<float> one = speckled_area(2.5, law, 1.0, 99);
    omp_set_num_threads(2);
    const std::vector<float> two = speckled_area(2.5, law, 1.0, 99);
    ASSERT_EQ(one.size(), two.size());
    EXPECT_EQ(std::memcmp(one.data(), two.data(), one.size() * sizeof(float)), 0);
    EXPECT_NE(one, speckled_area(2.5, law, 1.0, 100));
  }
  omp_set_num_threads(saved);
}

// apply_fading sets its per-bin constants up once; each pixel is still
// exactly fading_factor of its (seed, line, bin), N < 1 included.
TEST(Speckle, RasterIsThePixelFadingFactor) {
  const int lines = 7, bins = 5;
  const std::vector<double> looks = {0.6, 1.0, 1.05, 3.0, 17.5};
  for (FadingLaw law : {FadingLaw::exact_gamma, FadingLaw::seed_eq21}) {
    std::vector<float> p(static_cast<std::size_t>(lines * bins), 2.0f);
    apply_fading(p, lines, bins, looks, law, 42);
    for (int l = 0; l < lines; ++l) {
      for (int b = 0; b < bins; ++b) {
        const double y =
            fading_factor(law, looks[static_cast<std::size_t>(b)], 42,
                          static_cast<std::uint32_t>(l), static_cast<std::uint32_t>(b));
        EXPECT_EQ(p[static_cast<std::size_t>(l * bins + b)], static_cast<float>(2.0 * y))
            << l << " " << b;
      }
    }
  }
}

// The same over 120,000 pixels, enough to reach every way a draw can go (the
// squeeze in registers, the ziggurat's wedge and tail, v <= 0, the
// logarithmic test, N < 1's boost): each pixel is its fading_factor exactly.
TEST(Speckle, EveryPathOfTheDrawIsThePixelFadingFactor) {
  const int lines = 400, bins = 300;
  std::vector<double> looks(static_cast<std::size_t>(bins));
  for (int b = 0; b < bins; ++b) looks[static_cast<std::size_t>(b)] = 0.5 + 0.02 * b;
  for (FadingLaw law : {FadingLaw::exact_gamma, FadingLaw::seed_eq21}) {
    std::vector<float> p(static_cast<std::size_t>(lines * bins), 3.0f);
    apply_fading(p, lines, bins, looks, law, 7, 1000);
    for (int l = 0; l < lines; ++l) {
      for (int b = 0; b < bins; ++b) {
        const double y =
            fading_factor(law, looks[static_cast<std::size_t>(b)], 7,
                          static_cast<std::uint32_t>(1000 + l), static_cast<std::uint32_t>(b));
        ASSERT_EQ(p[static_cast<std::size_t>(l * bins + b)], static_cast<float>(3.0 * y))
            << l << " " << b;
      }
    }
  }
}

TEST(Speckle, NoDataAndShadowAreLeftAlone) {
  std::vector<float> img = {NAN, 0.0f, 1.0f, -1.0f};
  const std::vector<double> n(4, 1.0);
  apply_fading(img, 1, 4, n, FadingLaw::exact_gamma, 1);
  EXPECT_TRUE(std::isnan(img[0]));
  EXPECT_EQ(img[1], 0.0f);
  EXPECT_NE(img[2], 1.0f);
  EXPECT_EQ(img[3], -1.0f);
}

// A pixel's factor does not depend on its neighbours having data: whole
// chunks of no-data pixels (an oblique track's image outside the scene) are
// skipped, and a lone pixel with power among them is still faded.
TEST(Speckle, PixelsAmongNoDataGetTheirOwnFactor) {
  constexpr int kBins = 200;
  const std::vector<double> n(kBins, 3.0);
  std::vector<float> all(kBins, 1.0f);
  apply_fading(all, 1, kBins, n, FadingLaw::exact_gamma, 5);
  std::vector<float> sparse(kBins, NAN);
  for (int b : {5, 70, 71, 199}) sparse[static_cast<size_t>(b)] = 1.0f;
  apply_fading(sparse, 1, kBins, n, FadingLaw::exact_gamma, 5);
  for (int b = 0; b < kBins; ++b) {
    const auto i = static_cast<size_t>(b);
    if (b == 5 || b == 70 || b == 71 || b == 199) {
      EXPECT_EQ(sparse[i], all[i]) << b;
      EXPECT_NE(sparse[i], 1.0f) << b;
    } else {
      EXPECT_TRUE(std::isnan(sparse[i])) << b;
    }
  }
}

// N varies along range: each bin gets its own law.
TEST(Speckle, LooksPerBin) {
  constexpr int kLines = 20000, kBins = 2;
  std::vector<float> img(static_cast<size_t>(kLines) * kBins, 1.0f);
  const std::vector<double> n = {1.0, 100.0};
  apply_fading(img, kLines, kBins, n, FadingLaw::exact_gamma, 3);
  double s[2] = {0, 0}, s2[2] = {0, 0};
  for (int i = 0; i < kLines; ++i) {
    for (int k = 0; k < 2; ++k) {
      const double y = img[static_cast<size_t>(i) * kBins + static_cast<size_t>(k)];
      s[k] += y;
      s2[k] += y * y;
    }
  }
  for (int k = 0; k < 2; ++k) {
    const double mean = s[k] / kLines;
    const double cv = std::sqrt(s2[k] / kLines - mean * mean) / mean;
    EXPECT_NEAR(cv, 1.0 / std::sqrt(n[static_cast<size_t>(k)]),
                0.05 / std::sqrt(n[static_cast<size_t>(k)]));
  }
}

}  // namespace
}  // namespace ris
