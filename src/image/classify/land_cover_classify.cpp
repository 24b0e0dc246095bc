#include "ris/image/land_cover_classify.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "ris/util/error.h"

namespace ris {

namespace {

bool has_data(const ClassifyRequest& req, std::size_t i) {
  return req.valid.empty() || req.valid[i] != 0;
}

void check_request(const ClassifyRequest& req) {
  RIS_CHECK(req.rows > 0 && req.cols > 0 && !req.bands.empty());
  const std::size_t n = static_cast<std::size_t>(req.rows) * static_cast<std::size_t>(req.cols);
  for (const auto& b : req.bands) RIS_CHECK(b.size() == n);
  RIS_CHECK(req.valid.empty() || req.valid.size() == n);
}

// One band in dB, Gaussian-smoothed; with no-data pixels, by normalised
// convolution (the blur of the valid values over the blur of the validity)
// so that no-data never leaks into its neighbours. Without a mask, the plain
// blur (the bytes of the first version).
cv::Mat smoothed_db_band(const ClassifyRequest& req, const std::vector<float>& band) {
  const int n = req.rows * req.cols;
  cv::Mat db(req.rows, req.cols, CV_32F), weight(req.rows, req.cols, CV_32F);
  for (int i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const bool ok = has_data(req, k);
    db.at<float>(i) = ok ? 10.0f * std::log10(std::max(band[k], 1e-30f)) : 0.0f;
    weight.at<float>(i) = ok ? 1.0f : 0.0f;
  }
  if (req.smooth_sigma_px <= 0.0) return db;
  const cv::Size auto_size(0, 0);
  cv::GaussianBlur(db, db, auto_size, req.smooth_sigma_px, req.smooth_sigma_px, cv::BORDER_REFLECT);
  if (req.valid.empty()) return db;
  cv::GaussianBlur(weight, weight, auto_size, req.smooth_sigma_px, req.smooth_sigma_px,
                   cv::BORDER_REFLECT);
  for (int i = 0; i < n; ++i) {
    const float w = weight.at<float>(i);
    db.at<float>(i) = w > 1e-6f ? db.at<float>(i) / w : 0.0f;
  }
  return db;
}

// One row per pixel with data, one column per band: the smoothed dB values;
// index[row] is the pixel.
struct Samples {
  cv::Mat values;
  std::vector<std::size_t> index;
};

Samples smoothed_db_samples(const ClassifyRequest& req) {
  const std::size_t n = static_cast<std::size_t>(req.rows) * static_cast<std::size_t>(req.cols);
  const int nb = static_cast<int>(req.bands.size());
  Samples s;
  for (std::size_t i = 0; i < n; ++i)
    if (has_data(req, i)) s.index.push_back(i);
  s.values = cv::Mat(static_cast<int>(s.index.size()), nb, CV_32F);
  for (int b = 0; b < nb; ++b) {
    const cv::Mat db = smoothed_db_band(req, req.bands[static_cast<std::size_t>(b)]);
    for (std::size_t r = 0; r < s.index.size(); ++r)
      s.values.at<float>(static_cast<int>(r), b) = db.at<float>(static_cast<int>(s.index[r]));
  }
  return s;
}

// Labels and per-class means from each sample's class index (0..K-1).
ClassifyResult gather(const ClassifyRequest& req, const Samples& s,
                      const std::vector<int>& class_of_sample, std::vector<std::uint8_t> codes) {
  const std::size_t k = codes.size();
  const int nb = s.values.cols;
  ClassifyResult out;
  out.labels.assign(static_cast<std::size_t>(req.rows) * static_cast<std::size_t>(req.cols), 0);
  out.pixels.assign(k, 0);
  out.means.assign(k, std::vector<double>(static_cast<std::size_t>(nb)));
  for (std::size_t r = 0; r < s.index.size(); ++r) {
    const auto c = static_cast<std::size_t>(class_of_sample[r]);
    out.labels[s.index[r]] = codes[c];
    ++out.pixels[c];
    for (int b = 0; b < nb; ++b)
      out.means[c][static_cast<std::size_t>(b)] += s.values.at<float>(static_cast<int>(r), b);
  }
  for (std::size_t c = 0; c < k; ++c)
    for (double& m : out.means[c]) m /= std::max<double>(1.0, double(out.pixels[c]));
  out.codes = std::move(codes);
  return out;
}

}  // namespace

ClassifyResult classify_unsupervised(const ClassifyRequest& req) {
  check_request(req);
  RIS_CHECK(req.classes >= 2 && req.classes <= 255);
  const Samples s = smoothed_db_samples(req);
  if (s.index.size() < static_cast<std::size_t>(req.classes))
    throw std::invalid_argument("fewer pixels with data than classes");
  cv::Mat labels, centers;
  cv::theRNG() = cv::RNG(req.seed);  // k-means++ draws from the thread's RNG
  cv::kmeans(s.values, req.classes, labels,
             cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 100, 1e-4),
             std::max(1, req.attempts), cv::KMEANS_PP_CENTERS, centers);
  const int k = req.classes;
  std::vector<int> order(static_cast<std::size_t>(k));
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return centers.at<float>(a, 0) < centers.at<float>(b, 0); });
  std::vector<int> rank(static_cast<std::size_t>(k));
  for (int i = 0; i < k; ++i)
    rank[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])] = i;
  std::vector<int> cls(s.index.size());
  for (std::size_t r = 0; r < cls.size(); ++r)
    cls[r] = rank[static_cast<std::size_t>(labels.at<int>(static_cast<int>(r)))];
  std::vector<std::uint8_t> codes(static_cast<std::size_t>(k));
  std::iota(codes.begin(), codes.end(), std::uint8_t{1});
  return gather(req, s, cls, std::move(codes));
}

ClassifyResult classify_nearest_mean(const ClassifyRequest& req,
                                     std::span<const std::uint8_t> training) {
  check_request(req);
  RIS_CHECK(training.size() == req.bands[0].size());
  const Samples s = smoothed_db_samples(req);
  const int nb = s.values.cols;
  // Mean smoothed dB vector of each code's training pixels.
  std::vector<std::vector<double>> sum(256, std::vector<double>(static_cast<std::size_t>(nb)));
  std::vector<std::size_t> count(256, 0);
  for (std::size_t r = 0; r < s.index.size(); ++r) {
    const std::uint8_t code = training[s.index[r]];
    if (code == 0) continue;
    ++count[code];
    for (int b = 0; b < nb; ++b)
      sum[code][static_cast<std::size_t>(b)] += s.values.at<float>(static_cast<int>(r), b);
  }
  std::vector<std::uint8_t> codes;
  std::vector<std::vector<double>> means;
  for (int code = 1; code < 256; ++code) {
    const auto c = static_cast<std::size_t>(code);
    if (count[c] == 0) continue;
    codes.push_back(static_cast<std::uint8_t>(code));
    for (double& v : sum[c]) v /= double(count[c]);
    means.push_back(sum[c]);
  }
  if (codes.size() < 2)
    throw std::invalid_argument("training pixels with data for fewer than 2 categories");
  std::vector<int> cls(s.index.size());
  for (std::size_t r = 0; r < cls.size(); ++r) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < means.size(); ++c) {
      double d2 = 0.0;
      for (int b = 0; b < nb; ++b) {
        const double d =
            s.values.at<float>(static_cast<int>(r), b) - means[c][static_cast<std::size_t>(b)];
        d2 += d * d;
      }
      if (d2 < best) best = d2, cls[r] = static_cast<int>(c);
    }
  }
  return gather(req, s, cls, std::move(codes));
}

std::vector<ClassStatistics> class_statistics(const ClassifyRequest& req,
                                              const ClassifyResult& res) {
  const std::size_t nb = req.bands.size(), k = res.codes.size();
  std::vector<int> index_of_code(256, -1);
  for (std::size_t c = 0; c < k; ++c) index_of_code[res.codes[c]] = static_cast<int>(c);
  std::vector<ClassStatistics> out(k);
  std::vector<std::vector<double>> s1(k, std::vector<double>(nb)), s2 = s1;
  for (std::size_t i = 0; i < res.labels.size(); ++i) {
    const int c = index_of_code[res.labels[i]];
    if (res.labels[i] == 0 || c < 0) continue;
    const auto cc = static_cast<std::size_t>(c);
    ++out[cc].pixels;
    for (std::size_t b = 0; b < nb; ++b) {
      const double v = req.bands[b][i];
      s1[cc][b] += v, s2[cc][b] += v * v;
    }
  }
  for (std::size_t c = 0; c < k; ++c) {
    ClassStatistics& st = out[c];
    st.code = res.codes[c];
    const double n = double(st.pixels);
    for (std::size_t b = 0; b < nb; ++b) {
      const double mean = n > 0 ? s1[c][b] / n : 0.0;
      const double var = n > 1 ? (s2[c][b] - n * mean * mean) / (n - 1.0) : 0.0;
      st.mean_db.push_back(mean > 0 ? 10.0 * std::log10(mean)
                                    : -std::numeric_limits<double>::infinity());
      st.enl.push_back(var > 0 ? mean * mean / var : 0.0);
      st.m1.push_back(mean);
      st.m2.push_back(n > 0 ? s2[c][b] / n : 0.0);
    }
  }
  return out;
}

double k_shape_moments(double m1, double m2, double looks) {
  RIS_CHECK(m1 > 0.0 && looks > 0.0);
  const double excess = m2 / (m1 * m1) / (1.0 + 1.0 / looks) - 1.0;
  if (!(excess > 0.0)) return std::numeric_limits<double>::infinity();
  return 1.0 / excess;
}

}  // namespace ris
