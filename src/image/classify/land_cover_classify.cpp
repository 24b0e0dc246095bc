#include "ris/image/land_cover_classify.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "ris/util/error.h"

namespace ris {

namespace {

// One row per pixel, one column per band: the smoothed dB values.
cv::Mat smoothed_db_samples(const ClassifyRequest& req) {
  const int n = req.rows * req.cols;
  const int nb = static_cast<int>(req.bands.size());
  cv::Mat samples(n, nb, CV_32F);
  for (int b = 0; b < nb; ++b) {
    cv::Mat db(req.rows, req.cols, CV_32F);
    const std::vector<float>& band = req.bands[static_cast<std::size_t>(b)];
    for (int i = 0; i < n; ++i)
      db.at<float>(i) = 10.0f * std::log10(std::max(band[static_cast<std::size_t>(i)], 1e-30f));
    if (req.smooth_sigma_px > 0.0)
      cv::GaussianBlur(db, db, cv::Size(0, 0), req.smooth_sigma_px, req.smooth_sigma_px,
                       cv::BORDER_REFLECT);
    for (int i = 0; i < n; ++i) samples.at<float>(i, b) = db.at<float>(i);
  }
  return samples;
}

}  // namespace

ClassifyResult classify_unsupervised(const ClassifyRequest& req) {
  RIS_CHECK(req.rows > 0 && req.cols > 0 && !req.bands.empty());
  RIS_CHECK(req.classes >= 2 && req.classes <= 255);
  const std::size_t n = static_cast<std::size_t>(req.rows) * static_cast<std::size_t>(req.cols);
  for (const auto& b : req.bands) RIS_CHECK(b.size() == n);
  const cv::Mat samples = smoothed_db_samples(req);
  cv::Mat labels, centers;
  cv::theRNG() = cv::RNG(req.seed);  // k-means++ draws from the thread's RNG
  cv::kmeans(samples, req.classes, labels,
             cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-4),
             std::max(1, req.attempts), cv::KMEANS_PP_CENTERS, centers);
  const int k = req.classes, nb = samples.cols;
  std::vector<int> order(static_cast<std::size_t>(k));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return centers.at<float>(a, 0) < centers.at<float>(b, 0); });
  std::vector<int> rank(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i)
    rank[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = i;
  ClassifyResult out;
  out.labels.resize(n);
  out.pixels.assign(static_cast<std::size_t>(k), 0);
  out.means.assign(static_cast<std::size_t>(k), std::vector<double>(static_cast<std::size_t>(nb)));
  for (std::size_t i = 0; i < n; ++i) {
    const int c = rank[static_cast<std::size_t>(labels.at<int>(static_cast<int>(i)))];
    out.labels[i] = static_cast<std::uint8_t>(c + 1);
    ++out.pixels[static_cast<std::size_t>(c)];
    for (int b = 0; b < nb; ++b)
      out.means[static_cast<std::size_t>(c)][static_cast<std::size_t>(b)] +=
          samples.at<float>(static_cast<int>(i), b);
  }
  for (int c = 0; c < k; ++c)
    for (double& m : out.means[static_cast<std::size_t>(c)])
      m /= std::max<double>(1.0, double(out.pixels[static_cast<std::size_t>(c)]));
  return out;
}

double k_shape_moments(double m1, double m2, double looks) {
  RIS_CHECK(m1 > 0.0 && looks > 0.0);
  const double excess = m2 / (m1 * m1) / (1.0 + 1.0 / looks) - 1.0;
  if (!(excess > 0.0)) return std::numeric_limits<double>::infinity();
  return 1.0 / excess;
}

}  // namespace ris
