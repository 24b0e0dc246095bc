#include "ris/image/land_cover_classify.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>

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
