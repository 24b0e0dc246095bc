// Impulse-response measurement on analytic cuts: a sampled sinc^2 (the
// coherent SAR's response) and a box (the incoherent one).
#include "ris/image/impulse_response.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ris/util/units.h"

namespace ris {
namespace {

double sinc(double x) {
  return x == 0.0 ? 1.0 : std::sin(kPi * x) / (kPi * x);
}

// |h|^2 of h = sinc(0.886 x / rho), sampled every `spacing` (same units),
// with the peak `offset` samples off the middle sample.
std::vector<double> sinc2_cut(double rho, double spacing, double offset, int half) {
  std::vector<double> cut;
  for (int i = -half; i <= half; ++i) {
    const double h = sinc(0.88589 * (i - offset) * spacing / rho);
    cut.push_back(h * h);
  }
  return cut;
}

TEST(ImpulseResponse, SampledSincSquaredGivesItsDesignWidthAndSidelobes) {
  // 3 m resolution sampled at 1 m (3 samples per resolution cell), the peak
  // between samples: width within 2%, PSLR of sinc^2 -13.26 dB within 0.2 dB,
  // ISLR of the cut (+-24 samples = 7 null spacings) about -10 dB.
  for (double offset : {0.0, 0.3, 0.5}) {
    const IrfCut c = measure_irf_cut(sinc2_cut(3.0, 1.0, offset, 24), 1.0, IrfInterpolation::sinc);
    EXPECT_NEAR(c.width_m, 3.0, 0.06) << offset;
    EXPECT_NEAR(c.pslr_db, -13.26, 0.2) << offset;
    EXPECT_NEAR(c.islr_db, -10.2, 0.5) << offset;
  }
}

TEST(ImpulseResponse, BoxGivesItsWidthAndNoSidelobes) {
  // A box of 6 samples (linear interpolation): the half-power crossings lie
  // half a sample outside its end samples, so the width is 6 samples.
  std::vector<double> cut(31, 0.0);
  for (int i = 12; i <= 17; ++i) cut[static_cast<std::size_t>(i)] = 1.0;
  const IrfCut c = measure_irf_cut(cut, 2.0, IrfInterpolation::linear);
  EXPECT_NEAR(c.width_m, 12.0, 1e-9);  // 6 samples of 2 m
  EXPECT_LT(c.pslr_db, -100.0);        // nothing outside the main lobe
}

TEST(ImpulseResponse, FindsThePeakNearTheGivenPixelAndCutsBothAxes) {
  // A separable sinc^2 x sinc^2 response in a 64 x 64 image, peak at (30, 40)
  // while the caller points at (29, 38).
  const int lines = 64, bins = 64;
  std::vector<float> img(static_cast<std::size_t>(lines * bins));
  for (int l = 0; l < lines; ++l)
    for (int b = 0; b < bins; ++b) {
      const double ha = sinc(0.88589 * (l - 30) * 2.0 / 5.0);  // 2 m lines, 5 m azimuth
      const double hr = sinc(0.88589 * (b - 40) * 1.5 / 4.0);  // 1.5 m bins, 4 m range
      img[static_cast<std::size_t>(l * bins + b)] = static_cast<float>(ha * ha * hr * hr);
    }
  const IrfMeasurement m =
      measure_irf(img, lines, bins, 2.0, 1.5, 29, 38, 3, 20, IrfInterpolation::sinc);
  EXPECT_EQ(m.peak_line, 30);
  EXPECT_EQ(m.peak_bin, 40);
  EXPECT_NEAR(m.azimuth.width_m, 5.0, 0.1);
  EXPECT_NEAR(m.range.width_m, 4.0, 0.08);
  EXPECT_NEAR(m.pslr_db, -13.26, 0.3);
}

}  // namespace
}  // namespace ris
