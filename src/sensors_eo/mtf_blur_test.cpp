#include "ris/sensors_eo/mtf_blur.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace ris {
namespace {

// Amplitude of the cosine of frequency f (cycles/pixel) along the columns
// after the blur, by projection on the cosine over the middle of the image.
double measured_mtf(double sigma, double f) {
  const int rows = 4, cols = 256;
  std::vector<float> img(static_cast<std::size_t>(rows) * cols);
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      img[static_cast<std::size_t>(r) * cols + c] =
          static_cast<float>(1.0 + std::cos(2.0 * std::numbers::pi * f * c));
    }
  }
  blur_gaussian_masked(img, rows, cols, sigma);
  double num = 0, den = 0;
  for (int c = 64; c < 192; ++c) {
    const double w = std::cos(2.0 * std::numbers::pi * f * c);
    num += (img[static_cast<std::size_t>(cols) + c] - 1.0) * w;
    den += w * w;
  }
  return num / den;
}

TEST(MtfBlur, SigmaFromTheMtfAtNyquist) {
  EXPECT_DOUBLE_EQ(gaussian_sigma_px(1.0), 0.0);
  const double s = gaussian_sigma_px(0.3);
  EXPECT_NEAR(std::exp(-std::numbers::pi * std::numbers::pi * s * s / 2.0), 0.3, 1e-12);
}

// The blurred image's frequencies are multiplied by exp(-2 pi^2 s^2 f^2): at
// Nyquist exactly the sensor's MTF (a sampled Gaussian kernel would give
// about 0.59 for 0.3), at half Nyquist and at a tenth.
TEST(MtfBlur, ResponseOnThePixelGridIsTheMtf) {
  for (double m : {0.1, 0.3, 0.6}) {
    const double s = gaussian_sigma_px(m);
    for (double f : {0.5, 0.25, 0.05}) {
      const double expected = std::exp(-2.0 * std::numbers::pi * std::numbers::pi * s * s * f * f);
      EXPECT_NEAR(measured_mtf(s, f), expected, 0.005) << "MTF_N " << m << " f " << f;
    }
  }
}

// A uniform field stays uniform, and no-data pixels neither leak into their
// neighbours nor become data.
TEST(MtfBlur, NoDataStaysOutAndUniformStaysUniform) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> img(32 * 32, 5.0f);
  for (int r = 0; r < 32; ++r) img[static_cast<std::size_t>(r) * 32 + 10] = nan;
  blur_gaussian_masked(img, 32, 32, gaussian_sigma_px(0.2));
  for (int r = 0; r < 32; ++r) {
    for (int c = 0; c < 32; ++c) {
      const float v = img[static_cast<std::size_t>(r) * 32 + c];
      if (c == 10) {
        EXPECT_TRUE(std::isnan(v));
      } else {
        EXPECT_NEAR(v, 5.0f, 1e-5f);
      }
    }
  }
}

}  // namespace
}  // namespace ris
