#include "ris/sensors_eo/mtf_blur.h"

#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

namespace ris {
namespace {

constexpr double kPi = std::numbers::pi;
// The taps fall as 1/k^2 (the MTF periodised over the pixel grid has a kink
// at Nyquist): 32 each side leave the response at Nyquist within 0.005.
constexpr int kMinHalfTaps = 32;

// 2 int_0^1/2 exp(-2 pi^2 s^2 f^2) cos(2 pi f k) df by Simpson's rule (the
// integrand is smooth: 400 intervals leave errors below 1e-10).
double kernel_tap(double sigma, int k) {
  constexpr int kIntervals = 400;
  const double h = 0.5 / kIntervals;
  double sum = 0;
  for (int i = 0; i <= kIntervals; ++i) {
    const double f = i * h;
    const double w = (i == 0 || i == kIntervals) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    sum += w * std::exp(-2.0 * kPi * kPi * sigma * sigma * f * f) * std::cos(2.0 * kPi * f * k);
  }
  return 2.0 * sum * h / 3.0;
}

}  // namespace

double gaussian_sigma_px(double mtf_at_nyquist) {
  if (mtf_at_nyquist >= 1.0) return 0.0;
  return std::sqrt(-2.0 * std::log(mtf_at_nyquist)) / kPi;
}

std::vector<float> mtf_kernel(double sigma_px) {
  const int half = std::max(kMinHalfTaps, static_cast<int>(std::ceil(4.0 * sigma_px)));
  std::vector<double> g(2 * half + 1);
  double total = 0;
  for (int k = -half; k <= half; ++k) total += g[k + half] = kernel_tap(sigma_px, k);
  std::vector<float> out(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) out[i] = static_cast<float>(g[i] / total);
  return out;
}

void blur_gaussian_masked(std::vector<float>& image, int rows, int cols, double sigma_px) {
  if (sigma_px <= 0 || rows == 0 || cols == 0) return;
  cv::Mat value(rows, cols, CV_32F);
  cv::Mat mask(rows, cols, CV_32F);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const float v = image[static_cast<std::size_t>(r) * cols + c];
      const bool ok = std::isfinite(v);
      value.at<float>(r, c) = ok ? v : 0.0f;
      mask.at<float>(r, c) = ok ? 1.0f : 0.0f;
    }
  }
  const std::vector<float> taps = mtf_kernel(sigma_px);
  const cv::Mat k(static_cast<int>(taps.size()), 1, CV_32F, const_cast<float*>(taps.data()));
  cv::sepFilter2D(value, value, CV_32F, k, k, cv::Point(-1, -1), 0, cv::BORDER_REFLECT);
  cv::sepFilter2D(mask, mask, CV_32F, k, k, cv::Point(-1, -1), 0, cv::BORDER_REFLECT);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      float& v = image[static_cast<std::size_t>(r) * cols + c];
      const float m = mask.at<float>(r, c);
      if (std::isfinite(v) && m > 1e-6f) v = value.at<float>(r, c) / m;
    }
  }
}

}  // namespace ris
