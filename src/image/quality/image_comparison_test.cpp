// Co-registration and comparison measures (docs/quality.md, "ris compare"):
// a known integer and sub-pixel shift recovered within 0.05 pixels, identical
// images correlate 1, pure noise refuses to register, the mask overlap of a
// dark patch, the Hellinger distance of equal and disjoint histograms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <random>
#include <vector>

#include "ris/image/image_comparison.h"
#include "ris/image/image_registration.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

constexpr int kCols = 120, kRows = 100;

// A speckled scene: smooth relief of brightness (a few sinusoids and two
// bright blobs) times single-look speckle; returned in dB.
std::vector<float> scene_db(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::exponential_distribution<double> speckle(1.0);
  std::vector<float> db(kCols * kRows);
  for (int r = 0; r < kRows; ++r) {
    for (int c = 0; c < kCols; ++c) {
      const double m = 1.0 + 0.5 * std::sin(c * 0.21) * std::cos(r * 0.17) +
                       3.0 * std::exp(-((c - 40) * (c - 40) + (r - 30) * (r - 30)) / 50.0) +
                       2.0 * std::exp(-((c - 85) * (c - 85) + (r - 70) * (r - 70)) / 30.0);
      db[static_cast<std::size_t>(r * kCols + c)] =
          static_cast<float>(10.0 * std::log10(m * speckle(rng)));
    }
  }
  return db;
}

// b(x) = a(x - s), circularly, by the Fourier shift theorem along each axis.
std::vector<float> fourier_shift(const std::vector<float>& a, double sx, double sy) {
  using cpx = std::complex<double>;
  std::vector<cpx> v(a.begin(), a.end());
  const auto shift_line = [](std::vector<cpx>& line, double s) {
    const int n = static_cast<int>(line.size());
    std::vector<cpx> f(n), out(n);
    for (int k = 0; k < n; ++k)
      for (int x = 0; x < n; ++x) f[k] += line[x] * std::polar(1.0, -2.0 * kPi * k * x / n);
    for (int k = 0; k < n; ++k) {
      const int kk = k <= n / 2 ? k : k - n;
      f[k] *= std::polar(1.0, -2.0 * kPi * kk * s / n);
    }
    for (int x = 0; x < n; ++x) {
      for (int k = 0; k < n; ++k) out[x] += f[k] * std::polar(1.0, 2.0 * kPi * k * x / n);
      line[x] = out[x] / double(n);
    }
  };
  std::vector<cpx> line;
  for (int r = 0; r < kRows; ++r) {
    line.assign(v.begin() + r * kCols, v.begin() + (r + 1) * kCols);
    shift_line(line, sx);
    std::copy(line.begin(), line.end(), v.begin() + r * kCols);
  }
  for (int c = 0; c < kCols; ++c) {
    line.resize(kRows);
    for (int r = 0; r < kRows; ++r) line[r] = v[static_cast<std::size_t>(r * kCols + c)];
    shift_line(line, sy);
    for (int r = 0; r < kRows; ++r) v[static_cast<std::size_t>(r * kCols + c)] = line[r];
  }
  std::vector<float> out(a.size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<float>(v[i].real());
  return out;
}

TEST(ImageRegistration, RecoversIntegerAndSubPixelShiftsWithinATwentiethOfAPixel) {
  const std::vector<float> a = scene_db(1);
  double worst = 0.0;
  for (const auto& [sx, sy] :
       {std::pair{0.0, 0.0}, std::pair{3.0, -2.0}, std::pair{0.3, 1.0}, std::pair{-4.7, 0.25}}) {
    const std::vector<float> b = fourier_shift(a, sx, sy);
    const ImageRegistration r = register_images(a, b, kCols, kRows, {});
    // The issue asks for 0.05 pixels; measured 0.01, half the upsampled
    // correlation's 0.02-pixel step.
    EXPECT_NEAR(r.shift_x_px, sx, 0.05) << sx << ", " << sy;
    EXPECT_NEAR(r.shift_y_px, sy, 0.05) << sx << ", " << sy;
    EXPECT_GT(r.peak_z, 8.0);
    worst = std::max({worst, std::abs(r.shift_x_px - sx), std::abs(r.shift_y_px - sy)});
  }
  RecordProperty("worst_shift_error_px", std::to_string(worst));
}

TEST(ImageRegistration, PureNoiseRefusesToRegister) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> n(0.0, 5.0);
  std::vector<float> a(kCols * kRows), b(kCols * kRows);
  for (float& x : a) x = static_cast<float>(n(rng));
  for (float& x : b) x = static_cast<float>(n(rng));
  EXPECT_THROW(register_images(a, b, kCols, kRows, {}), InputError);
}

TEST(ImageComparison, IdenticalImagesCorrelateOneWithNoBiasAndNoHistogramDistance) {
  const std::vector<float> db = scene_db(2);
  std::vector<float> p(db.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = std::pow(10.0f, db[i] / 10.0f);
  for (int w : {1, 3, 5, 9}) {
    const WindowAgreement g = window_agreement(p, p, kCols, kRows, w);
    EXPECT_NEAR(g.pearson, 1.0, 1e-12) << w;
    EXPECT_NEAR(g.spearman, 1.0, 1e-12) << w;
    EXPECT_EQ(g.bias_db, 0.0);
    EXPECT_EQ(g.blocks, (kCols / w) * (kRows / w));
  }
  EXPECT_NEAR(histogram_hellinger(p, p), 0.0, 1e-7);
  // Twice the power: the bias is 3.01 dB at every window, correlation still 1.
  std::vector<float> q(p);
  for (float& x : q) x *= 2.0f;
  EXPECT_NEAR(window_agreement(p, q, kCols, kRows, 5).bias_db, 10.0 * std::log10(2.0), 1e-5);
  // Disjoint histograms: 1.
  std::vector<float> far(p.size(), 1e-10f), near(p.size(), 1.0f);
  EXPECT_NEAR(histogram_hellinger(far, near), 1.0, 1e-12);
}

TEST(ImageComparison, ShadowMaskOverlapsTheDarkPatchOfTheImage) {
  // A dark 20 x 20 patch (10% of the 2 x 10 = 20% darkest...) in uniform
  // speckle-free ground; the mask marks the same patch, then a patch beside it.
  const int cols = 100, rows = 40;
  std::vector<float> img(cols * rows, 1.0f);
  std::vector<std::uint8_t> same(img.size(), 0), beside(img.size(), 0);
  for (int r = 10; r < 30; ++r)
    for (int c = 20; c < 40; ++c) {
      img[static_cast<std::size_t>(r * cols + c)] = 0.001f;
      same[static_cast<std::size_t>(r * cols + c)] = 1;
      beside[static_cast<std::size_t>(r * cols + c + 40)] = 1;
    }
  const MaskAgreement s = mask_agreement(same, 1, img, cols, rows, true);
  const MaskAgreement b = mask_agreement(beside, 1, img, cols, rows, true);
  EXPECT_GT(s.iou, 0.6);  // the 5 x 5 smoothing rounds the patch's border
  EXPECT_LT(b.iou, 0.05);
}

}  // namespace
}  // namespace ris
