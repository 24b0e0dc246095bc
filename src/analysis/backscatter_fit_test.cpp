// The fit of ris/analysis/backscatter_fit.h against cases with a known
// answer: exact curves at one angle per bin, single-look speckle of known
// mean (the linear mean is unbiased, the mean of dB 2.51 dB low), the
// counts that refuse a category, and the table read back by ris.
#include "ris/analysis/backscatter_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "ris/backscatter/library.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

// dB = -5 - 0.3 t + 0.002 t^2 (t in degrees): a curve the quadratic holds.
double curve_db(double t) {
  return -5.0 - 0.3 * t + 0.002 * t * t;
}

struct Pixels {
  std::vector<float> sigma0, incidence;
  std::vector<std::int32_t> category;
  void add(std::int32_t c, double t, double s) {
    category.push_back(c);
    incidence.push_back(static_cast<float>(t));
    sigma0.push_back(static_cast<float>(s));
  }
};

TEST(BackscatterFit, RecoversACurveSampledAtOneAnglePerBinExactly) {
  Pixels p;
  for (int k = 20; k < 40; ++k)
    for (int i = 0; i < 60; ++i) p.add(7, k + 0.25, std::pow(10.0, curve_db(k + 0.25) / 10.0));
  const std::vector<CategoryFit> fits = fit_backscatter(p.sigma0, p.incidence, p.category, {});
  ASSERT_EQ(fits.size(), 1u);
  const CategoryFit& f = fits[0];
  ASSERT_TRUE(f.fitted) << f.reason;
  EXPECT_EQ(f.category, 7);
  ASSERT_EQ(f.bins.size(), 20u);
  for (const auto& b : f.bins) {
    EXPECT_NEAR(b.table_db, curve_db(b.angle_deg), 1e-5);  // float32 pixels
    EXPECT_EQ(b.pixels, 60);
    EXPECT_NEAR(b.cv, 0.0, 1e-6);
  }
  EXPECT_NEAR(f.quad[0], -5.0, 1e-3);
  EXPECT_NEAR(f.quad[1], -0.3, 1e-4);
  EXPECT_NEAR(f.quad[2], 0.002, 1e-6);
  EXPECT_LT(f.rms_residual_db, 1e-4);
}

// Single-look speckle: I = m E, E exponential of mean 1 (MODEL.md section 3,
// "Fading", N = 1). Bin means of linear I are within 4 standard errors of
// 10 log10 m; the mean of 10 log10 I would be 10 log10(e) x 0.5772 = 2.507
// dB below it (the Euler-gamma bias), which the tolerance excludes.
TEST(BackscatterFit, TheMeanOfLinearSigma0IsUnbiasedUnderSpeckle) {
  std::mt19937_64 rng(34);
  std::exponential_distribution<double> speckle(1.0);
  std::uniform_real_distribution<double> angle(30.0, 35.0);
  Pixels p;
  double mean_db_of_pixels = 0.0;
  const int n = 100000;
  for (int i = 0; i < n; ++i) {
    const double t = angle(rng);
    const double s = std::pow(10.0, curve_db(t) / 10.0) * speckle(rng);
    p.add(1, t, s);
    mean_db_of_pixels += (10.0 * std::log10(s) - curve_db(t)) / n;
  }
  EXPECT_NEAR(mean_db_of_pixels, -2.507, 0.03);  // what a mean of dB would give
  const CategoryFit f = fit_backscatter(p.sigma0, p.incidence, p.category, {})[0];
  ASSERT_EQ(f.bins.size(), 5u);
  for (const auto& b : f.bins) {
    // The curve's value at the bin's mean angle is not its mean over the
    // bin: the curve is within 0.002 dB of linear over a degree.
    EXPECT_NEAR(b.table_db, curve_db(b.angle_deg), 4.0 * b.se_db + 0.002) << b.angle_deg;
    EXPECT_NEAR(b.cv, 1.0, 0.05);  // single look: s / m = 1
    EXPECT_NEAR(b.se_db, 4.3429 / std::sqrt(static_cast<double>(b.pixels)), 0.003);
  }
}

TEST(BackscatterFit, TooFewPixelsOrBinsLeaveACategoryUnfittedWithTheReason) {
  Pixels p;
  for (int k = 20; k < 30; ++k)
    for (int i = 0; i < 100; ++i) p.add(1, k + 0.5, 0.1);       // 1000 pixels, 10 bins
  for (int i = 0; i < 100; ++i) p.add(2, 25.5, 0.1);            // one bin
  for (int i = 0; i < 40; ++i) p.add(3, 25.5 + i * 0.25, 0.1);  // 4 per bin
  p.add(-1, 25.0, 0.1);                                         // excluded
  p.add(4, 95.0, 0.1);                                          // back-facing
  p.add(4, 25.0, std::nan(""));                                 // no data
  p.add(4, 25.0, 0.0);                                          // zero power
  const std::vector<CategoryFit> fits = fit_backscatter(p.sigma0, p.incidence, p.category, {});
  ASSERT_EQ(fits.size(), 3u);  // 4 has no valid pixel, -1 is excluded
  EXPECT_TRUE(fits[0].fitted);
  EXPECT_EQ(fits[0].used_pixels, 1000);
  EXPECT_FALSE(fits[1].fitted);
  EXPECT_NE(fits[1].reason.find("100 pixels in 1 incidence bins"), std::string::npos)
      << fits[1].reason;
  EXPECT_FALSE(fits[2].fitted);
  EXPECT_EQ(fits[2].pixels, 40);
  EXPECT_EQ(fits[2].used_pixels, 0);
  BackscatterFitOptions o;
  o.min_category_pixels = 1001;
  EXPECT_FALSE(fit_backscatter(p.sigma0, p.incidence, p.category, o)[0].fitted);
  const std::vector<float> short_list(3, 0.1f);
  EXPECT_THROW(fit_backscatter(short_list, p.incidence, p.category, {}), std::invalid_argument);
  o = {};
  o.bin_deg = 0.0;
  EXPECT_THROW(fit_backscatter(p.sigma0, p.incidence, p.category, o), std::invalid_argument);
}

TEST(BackscatterFit, TheWrittenTableIsWhatRisReadsBack) {
  Pixels p;
  for (int k = 20; k < 40; ++k)
    for (int i = 0; i < 60; ++i) {
      p.add(5, k + 0.3, std::pow(10.0, curve_db(k + 0.3) / 10.0));
      p.add(9, k + 0.6, std::pow(10.0, (curve_db(k + 0.6) - 3.0) / 10.0));
    }
  const std::vector<CategoryFit> fits = fit_backscatter(p.sigma0, p.incidence, p.category, {});
  const RadarBand band{1.2575e9, Polarisation::HV};
  const std::string csv = backscatter_table_csv(
      fits, band, [](std::int32_t c) { return c == 5 ? std::string("grass") : std::string(); },
      "test", false);
  test::TempDir dir;
  test::write_file(dir / "t.csv", csv);
  const auto src = load_sigma0_source((dir / "t.csv").string());
  EXPECT_EQ(src->category_name(5), "grass");
  for (const CategoryFit& f : fits) {
    for (const auto& b : f.bins) {
      // At the angle as the table has it (1e-4 deg).
      const double s = src->sigma0(static_cast<std::uint16_t>(f.category),
                                   deg_to_rad(std::round(b.angle_deg * 1e4) / 1e4), band);
      EXPECT_NEAR(10.0 * std::log10(s), b.table_db, 1e-3) << f.category << " " << b.angle_deg;
    }
  }
  // No clamp: an angle outside the fitted range is refused.
  EXPECT_ANY_THROW(src->sigma0(5, deg_to_rad(50.0), band));
  // Another band is not in the table.
  EXPECT_ANY_THROW(src->sigma0(5, deg_to_rad(30.0), RadarBand{1.3e9, Polarisation::HV}));
}

}  // namespace
}  // namespace ris
