// Image-quality measures against their laws (docs/quality.md): speckle ENL of
// exponential (single look) and Gamma(L) (L looks) intensity, the automatic
// homogeneous regions across an edge, Gaussian class separability in closed
// form, the 10-90% width of an ideal and a ramped edge, dB percentiles.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ris/image/class_separability.h"
#include "ris/image/edge_sharpness.h"
#include "ris/image/intensity_histogram.h"
#include "ris/image/speckle_statistics.h"
#include "ris/util/error.h"

namespace ris {
namespace {

// L-look speckle of unit mean: Gamma(L, 1/L), times `mean`.
std::vector<float> speckle(int n, int looks, double mean, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::gamma_distribution<double> g(looks, 1.0 / looks);
  std::vector<float> v(static_cast<std::size_t>(n));
  for (float& x : v) x = static_cast<float>(mean * g(rng));
  return v;
}

TEST(SpeckleStatistics, SingleLookExponentialSpeckleHasEnlOneAndCvOne) {
  const std::vector<float> img = speckle(500 * 500, 1, 3.0, 1);
  const IntensityView v{img, 500, 500, {}};
  const SpeckleSummary s = pooled_speckle(v, {PixelBox{0, 0, 500, 500}});
  // The estimate's standard error: sqrt((kurtosis - 1) / n) = sqrt(8 / 250000)
  // = 0.6% for the exponential law; the 3% is five of those.
  EXPECT_NEAR(s.enl, 1.0, 0.03);
  EXPECT_NEAR(s.cv, 1.0 / std::sqrt(s.enl), 1e-12);
  EXPECT_NEAR(s.radiometric_resolution_db, 10.0 * std::log10(1.0 + 1.0 / std::sqrt(s.enl)), 1e-12);
  EXPECT_NEAR(radiometric_resolution_db(1.0), 3.0103, 1e-4);  // 10 log10(2)
}

TEST(SpeckleStatistics, FourLookAverageHasEnlFour) {
  const std::vector<float> img = speckle(500 * 500, 4, 0.2, 2);
  const IntensityView v{img, 500, 500, {}};
  const SpeckleSummary s = pooled_speckle(v, {PixelBox{0, 0, 500, 500}});
  EXPECT_NEAR(s.enl / 4.0, 1.0, 0.03);  // standard error 0.4%
  EXPECT_NEAR(s.cv, 0.5, 0.5 * 0.03);
}

TEST(SpeckleStatistics, AutomaticRegionsLeaveOutTheWindowsAcrossAnEdge) {
  // Single-look speckle, mean 1 left of column 250 and 10 right of it: as one
  // region the edge makes the ENL far below 1; the automatic windows (16 x 16,
  // the column-240 windows straddle the edge) find single-look speckle.
  std::vector<float> img = speckle(500 * 500, 1, 1.0, 3);
  for (int r = 0; r < 500; ++r)
    for (int c = 250; c < 500; ++c) img[static_cast<std::size_t>(r * 500 + c)] *= 10.0f;
  const IntensityView v{img, 500, 500, {}};
  EXPECT_LT(pooled_speckle(v, {PixelBox{0, 0, 500, 500}}).enl, 0.5);
  const std::vector<PixelBox> boxes = homogeneous_windows(v, {});
  for (const PixelBox& b : boxes) {
    EXPECT_FALSE(b.col0 < 250 && b.col0 + b.cols > 250) << "window at column " << b.col0;
  }
  const SpeckleSummary s = pooled_speckle(v, boxes);
  // Measured 1.01: the rule drops the few speckle windows whose CV is beyond
  // median + 3 MAD too, a small bias towards more looks.
  EXPECT_NEAR(s.enl, 1.0, 0.05);
  EXPECT_GT(s.regions, 800);
  RecordProperty("enl", std::to_string(s.enl));
}

TEST(SpeckleStatistics, MaskedAndNoDataPixelsAreLeftOut) {
  std::vector<float> img = speckle(100 * 100, 1, 1.0, 4);
  std::vector<std::uint8_t> mask(img.size(), 0);
  for (std::size_t i = 0; i < img.size(); i += 7) img[i] = std::numeric_limits<float>::quiet_NaN();
  for (std::size_t i = 3; i < img.size(); i += 11) img[i] = 1e6f, mask[i] = 1;  // masked outliers
  const IntensityView v{img, 100, 100, mask};
  const RegionStatistics r = region_statistics(v, PixelBox{0, 0, 100, 100});
  // 1429 NaNs (every 7th), 909 masked (every 11th from 3), 130 both.
  EXPECT_EQ(r.pixels, 10000 - 1429 - 909 + 130);
  EXPECT_LT(r.mean, 1.2);
  // A constant image has no spread: an error, not an ENL of infinity.
  const std::vector<float> flat(400, 2.0f);
  EXPECT_THROW(pooled_speckle(IntensityView{flat, 20, 20, {}}, {PixelBox{0, 0, 20, 20}}),
               InputError);
  const std::vector<float> none(400, std::numeric_limits<float>::quiet_NaN());
  EXPECT_THROW(pooled_speckle(IntensityView{none, 20, 20, {}}, {PixelBox{0, 0, 20, 20}}),
               InputError);
  EXPECT_THROW(intensity_histogram(IntensityView{none, 20, 20, {}}), InputError);
}

TEST(ClassSeparability, GaussianClassesInDbGiveTheClosedFormDistances) {
  // Two classes whose dB values are Gaussian: mean -10, sd 1 and mean -13,
  // sd 2. B = 9 / (4 * 5) + 0.5 ln(5 / 4) = 0.56657; JM = 2 (1 - e^-B).
  std::mt19937_64 rng(5);
  std::normal_distribution<double> a(-10.0, 1.0), b(-13.0, 2.0);
  const int n = 200000;
  std::vector<float> img(2 * n);
  std::vector<double> cat(2 * n);
  for (int i = 0; i < n; ++i) {
    img[i] = static_cast<float>(std::pow(10.0, a(rng) / 10.0)), cat[i] = 1;
    img[n + i] = static_cast<float>(std::pow(10.0, b(rng) / 10.0)), cat[n + i] = 2;
  }
  const IntensityView v{img, 2 * n, 1, {}};
  const std::vector<CategoryStatistics> c = category_statistics(v, cat);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_NEAR(c[0].mean_db, -10.0, 0.01);
  EXPECT_NEAR(c[1].std_db, 2.0, 0.01);
  const Separability s = separability(c[0], c[1]);
  const double B = 9.0 / 20.0 + 0.5 * std::log(5.0 / 4.0);
  EXPECT_NEAR(s.bhattacharyya, B, 0.005);  // sampling error ~1e-3
  EXPECT_NEAR(s.jeffries_matusita, 2.0 * (1.0 - std::exp(-B)), 0.005);
  // The same class: no distance.
  const Separability same = separability(c[0], c[0]);
  EXPECT_DOUBLE_EQ(same.bhattacharyya, 0.0);
  EXPECT_DOUBLE_EQ(same.jeffries_matusita, 0.0);
}

TEST(EdgeSharpness, IdealStepIsZeroPointEightPixelsAndARampIsWider) {
  const int cols = 64, rows = 10;
  std::vector<float> step(cols * rows), ramp(cols * rows);
  std::vector<std::uint8_t> mask(cols * rows, 0);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const std::size_t i = static_cast<std::size_t>(r * cols + c);
      mask[i] = c >= 32 ? 1 : 0;
      step[i] = c >= 32 ? 0.0f : 10.0f;
      // A linear fall from 10 to 0 over columns 28-36 (8 pixels).
      ramp[i] = static_cast<float>(std::clamp(10.0 - (c - 28) * 10.0 / 8.0, 0.0, 10.0));
    }
  }
  const EdgeSharpness e = edge_sharpness(step, mask, cols, rows, 1);
  EXPECT_EQ(e.edges, rows);
  EXPECT_NEAR(e.width_px, 0.8, 1e-9);
  // The ramp falls 10% to 90% of its 10 units over 0.8 x 8 pixels.
  EXPECT_NEAR(edge_sharpness(ramp, mask, cols, rows, 1).width_px, 6.4, 1e-9);
  EXPECT_THROW(edge_sharpness(step, std::vector<std::uint8_t>(cols * rows, 0), cols, rows, 1),
               InputError);
}

TEST(IntensityHistogram, PercentilesAndDynamicRangeOfKnownDbValues) {
  // 10001 pixels at -50, -49.99, ..., +50 dB.
  std::vector<float> img;
  for (int i = 0; i <= 10000; ++i)
    img.push_back(static_cast<float>(std::pow(10.0, (-50.0 + 0.01 * i) / 10.0)));
  const IntensityHistogram h = intensity_histogram(IntensityView{img, 10001, 1, {}});
  EXPECT_NEAR(h.p1_db, -49.0, 1e-3);
  EXPECT_NEAR(h.p50_db, 0.0, 1e-3);
  EXPECT_NEAR(h.p99_db, 49.0, 1e-3);
  EXPECT_NEAR(h.dynamic_range_db(), 98.0, 2e-3);
  EXPECT_EQ(h.first_bin_db, -50.0);
  ASSERT_EQ(h.counts.size(), 101u);
  EXPECT_EQ(h.counts[0], 100);
  std::int64_t total = 0;
  for (auto n : h.counts) total += n;
  EXPECT_EQ(total, 10001);
}

}  // namespace
}  // namespace ris
