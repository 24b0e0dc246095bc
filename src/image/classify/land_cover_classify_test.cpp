#include "ris/image/land_cover_classify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>

namespace ris {
namespace {

// Four 64x64 quadrants, 6 dB apart, with multiplicative speckle
// Gamma(L, 1/L), L = 4, from a fixed seed.
ClassifyRequest quadrants(std::vector<int>& truth) {
  ClassifyRequest req;
  req.rows = req.cols = 128;
  req.classes = 4;
  const float means[4] = {0.05f, 0.2f, 0.8f, 3.2f};
  std::mt19937_64 rng(42);
  std::gamma_distribution<float> speckle(4.0f, 0.25f);
  req.bands.assign(1, std::vector<float>(128 * 128));
  truth.assign(128 * 128, 0);
  for (int r = 0; r < 128; ++r)
    for (int c = 0; c < 128; ++c) {
      const int region = (r >= 64 ? 2 : 0) + (c >= 64 ? 1 : 0);
      truth[static_cast<std::size_t>(r * 128 + c)] = region;
      req.bands[0][static_cast<std::size_t>(r * 128 + c)] = means[region] * speckle(rng);
    }
  return req;
}

// Per region: intersection over union with the class that holds most of it.
std::vector<double> region_iou(const std::vector<int>& truth,
                               const std::vector<std::uint8_t>& lab) {
  std::vector<double> out;
  for (int region = 0; region < 4; ++region) {
    std::map<int, int> votes;
    for (std::size_t i = 0; i < truth.size(); ++i)
      if (truth[i] == region) ++votes[lab[i]];
    int best = 0, most = -1;
    for (auto [k, v] : votes)
      if (v > most) best = k, most = v;
    double inter = 0, uni = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
      const bool a = truth[i] == region, b = lab[i] == best;
      inter += a && b;
      uni += a || b;
    }
    out.push_back(inter / uni);
  }
  return out;
}

TEST(LandCoverClassify, RecoversSpeckledRegions) {
  std::vector<int> truth;
  const ClassifyResult res = classify_unsupervised(quadrants(truth));
  const std::vector<double> iou = region_iou(truth, res.labels);
  for (int r = 0; r < 4; ++r) {
    EXPECT_GT(iou[static_cast<std::size_t>(r)], 0.95) << "region " << r;
    std::printf("region %d IoU %.4f\n", r, iou[static_cast<std::size_t>(r)]);
  }
  // Classes numbered by increasing mean: the darkest quadrant is class 1.
  EXPECT_EQ(res.labels[0], 1);
  EXPECT_EQ(res.labels[128 * 128 - 1], 4);
}

TEST(LandCoverClassify, IsDeterministic) {
  std::vector<int> truth;
  const ClassifyRequest req = quadrants(truth);
  EXPECT_EQ(classify_unsupervised(req).labels, classify_unsupervised(req).labels);
}

// No-data pixels (a 20-column stripe across all four quadrants and a
// scatter of single pixels, as a real product's fill and dropouts) are
// labelled 0, take no part in the smoothing (normalised convolution) and
// leave the regions' IoU over the pixels with data above 0.95.
TEST(LandCoverClassify, NoDataPixelsAreLeftOutAndLabelledZero) {
  std::vector<int> truth;
  ClassifyRequest req = quadrants(truth);
  req.valid.assign(128 * 128, 1);
  for (int r = 0; r < 128; ++r)
    for (int c = 0; c < 128; ++c) {
      const std::size_t i = static_cast<std::size_t>(r * 128 + c);
      if ((c >= 54 && c < 74) || (r * 31 + c * 17) % 97 == 0) {
        req.valid[i] = 0;
        req.bands[0][i] = 1e6f;  // a value the smoothing must never see
      }
    }
  const ClassifyResult res = classify_unsupervised(req);
  std::vector<int> truth_with_data = truth;
  std::size_t zero = 0, invalid = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    invalid += req.valid[i] == 0;
    zero += res.labels[i] == 0;
    if (req.valid[i] == 0) truth_with_data[i] = -1;  // in no region
    if (req.valid[i] == 0) {
      EXPECT_EQ(res.labels[i], 0) << i;
    }
  }
  EXPECT_EQ(zero, invalid);
  std::size_t counted = 0;
  for (const std::size_t n : res.pixels) counted += n;
  EXPECT_EQ(counted + invalid, truth.size());
  const std::vector<double> iou = region_iou(truth_with_data, res.labels);
  for (int r = 0; r < 4; ++r) {
    std::printf("with no-data: region %d IoU %.4f\n", r, iou[static_cast<std::size_t>(r)]);
    EXPECT_GT(iou[static_cast<std::size_t>(r)], 0.95) << "region " << r;
  }
  // The class means (of smoothed dB) stay those of the regions, 6.02 dB
  // apart from -13.01 dB, less the log's bias for L-look speckle,
  // E[10 log10 s] = 10 / ln 10 (psi(L) - ln L) = -0.565 dB for L = 4
  // (Oliver & Quegan 1998, section 4.3; psi(4) = 1 + 1/2 + 1/3 - 0.5772),
  // within 0.25 dB: a leaked 60 dB no-data value would move them by more.
  const double psi4 = 1.0 + 0.5 + 1.0 / 3.0 - 0.5772156649;
  const double log_bias_db = 10.0 / std::log(10.0) * (psi4 - std::log(4.0));
  for (int c = 0; c < 4; ++c)
    EXPECT_NEAR(res.means[static_cast<std::size_t>(c)][0], -13.01 + 6.02 * c + log_bias_db, 0.25)
        << c;
}

// Supervised: a 16 x 16 training box inside each quadrant, coded 10, 20,
// 30 and 40 (deliberately not 1..4): every quadrant takes its box's code
// with IoU > 0.95, and the codes are the training codes in increasing order.
TEST(LandCoverClassify, NearestMeanTakesTheTrainingCodes) {
  std::vector<int> truth;
  const ClassifyRequest req = quadrants(truth);
  std::vector<std::uint8_t> training(128 * 128, 0);
  const std::uint8_t code[4] = {30, 10, 40, 20};  // quadrant -> code
  for (int q = 0; q < 4; ++q)
    for (int r = 0; r < 16; ++r)
      for (int c = 0; c < 16; ++c) {
        const int row = (q >= 2 ? 64 : 0) + 24 + r, col = (q % 2 ? 64 : 0) + 24 + c;
        training[static_cast<std::size_t>(row * 128 + col)] = code[q];
      }
  const ClassifyResult res = classify_nearest_mean(req, training);
  EXPECT_EQ(res.codes, (std::vector<std::uint8_t>{10, 20, 30, 40}));
  for (int q = 0; q < 4; ++q) {
    double inter = 0, uni = 0;
    for (std::size_t i = 0; i < truth.size(); ++i) {
      const bool a = truth[i] == q, b = res.labels[i] == code[q];
      inter += a && b;
      uni += a || b;
    }
    std::printf("nearest mean: region %d (code %d) IoU %.4f\n", q, code[q], inter / uni);
    EXPECT_GT(inter / uni, 0.95) << "region " << q;
  }
  std::vector<std::uint8_t> one(128 * 128, 0);
  one[0] = 5;
  EXPECT_THROW(classify_nearest_mean(req, one), std::invalid_argument);
}

// Per-class statistics of the linear image: on the true labelling, each
// quadrant's mean within 0.1 dB of its mean power (4096 pixels of 4-look
// speckle: the standard error of the mean is 0.5 / 64 = 0.8 %, 0.034 dB) and
// its ENL within 0.4 of 4 (the ENL estimate's relative standard error is
// about sqrt((2 + 6/L)/n) = 2.9 %, 0.12 here; 0.4 is 3.4 of them).
TEST(LandCoverClassify, ClassStatisticsGiveMeanAndLooks) {
  std::vector<int> truth;
  const ClassifyRequest req = quadrants(truth);
  ClassifyResult res;
  res.codes = {1, 2, 3, 4};
  for (const int t : truth) res.labels.push_back(static_cast<std::uint8_t>(t + 1));
  const std::vector<ClassStatistics> st = class_statistics(req, res);
  ASSERT_EQ(st.size(), 4U);
  const double mean_db[4] = {-13.0103, -6.9897, -0.9691, 5.0515};
  for (std::size_t c = 0; c < 4; ++c) {
    std::printf("class %zu: mean %.3f dB, ENL %.3f\n", c + 1, st[c].mean_db[0], st[c].enl[0]);
    EXPECT_EQ(st[c].pixels, 4096U);
    EXPECT_NEAR(st[c].mean_db[0], mean_db[c], 0.1);
    EXPECT_NEAR(st[c].enl[0], 4.0, 0.4);
  }
}

// Method-of-moments nu on K-distributed single-look intensity of known nu:
// the mean of 10 estimates (each from 100000 samples) within 4 standard
// errors of the mean (the spread measured over the 10 draws).
TEST(KShapeMoments, RecoversKnownShape) {
  std::mt19937_64 rng(7);
  std::exponential_distribution<double> speckle(1.0);
  for (const double nu :
       std::vector<double>{0.5, 2.0, 10.0, std::numeric_limits<double>::infinity()}) {
    std::vector<double> inv;  // 1/nu-hat: finite for nu = inf too
    for (int rep = 0; rep < 10; ++rep) {
      double m1 = 0, m2 = 0;
      const int n = 100000;
      std::gamma_distribution<double> texture(std::isinf(nu) ? 1.0 : nu,
                                              std::isinf(nu) ? 1.0 : 1.0 / nu);
      for (int i = 0; i < n; ++i) {
        const double v = (std::isinf(nu) ? 1.0 : texture(rng)) * speckle(rng);
        m1 += v, m2 += v * v;
      }
      m1 /= n, m2 /= n;
      const double est = k_shape_moments(m1, m2, 1.0);
      inv.push_back(m2 / (m1 * m1) / 2.0 - 1.0);
      if (!std::isinf(est)) {
        EXPECT_NEAR(1.0 / est, inv.back(), 1e-12);
      } else {
        EXPECT_LE(inv.back(), 0.0);
      }
    }
    double mean = 0, var = 0;
    for (double x : inv) mean += x / 10.0;
    for (double x : inv) var += (x - mean) * (x - mean) / 9.0;
    const double se = std::sqrt(var / 10.0);
    const double truth = std::isinf(nu) ? 0.0 : 1.0 / nu;
    std::printf("nu %g: 1/nu-hat %.5f +- %.5f (nu-hat %.3f)\n", nu, mean, se, 1.0 / mean);
    EXPECT_NEAR(mean, truth, 4.0 * se + 1e-3) << "nu " << nu;
  }
  EXPECT_TRUE(std::isinf(k_shape_moments(1.0, 2.0, 1.0)));
  EXPECT_DOUBLE_EQ(k_shape_moments(1.0, 3.0, 1.0), 2.0);  // 2 (1 + 1/2) = 3
}

}  // namespace
}  // namespace ris
