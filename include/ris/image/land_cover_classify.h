#pragma once

// Unsupervised land-cover classification of a multi-band raster (issue 34
// item 4, docs/classify.md): every band to dB, smoothed (OpenCV's Gaussian
// blur: the speckle of a single look has a dB spread of 5.6 dB), then
// k-means (k-means++ seeding from a seeded cv::RNG, several attempts) over
// the smoothed pixel vectors. Classes are numbered 1..K in increasing mean
// of the first band, so the numbering does not depend on k-means' order.
#include <cstdint>
#include <vector>

namespace ris {

struct ClassifyRequest {
  int rows = 0, cols = 0;
  std::vector<std::vector<float>> bands;  // each rows*cols, linear power (> 0)
  int classes = 4;                        // K, 2..255
  double smooth_sigma_px = 1.0;           // Gaussian smoothing of the dB bands
  int attempts = 3;
  std::uint64_t seed = 1;
};

struct ClassifyResult {
  std::vector<std::uint8_t> labels;        // rows*cols, 1..K
  std::vector<std::vector<double>> means;  // [class][band], dB, of the smoothed bands
  std::vector<std::size_t> pixels;         // per class
};

ClassifyResult classify_unsupervised(const ClassifyRequest& req);

// K-distribution shape nu by the method of moments from the first two
// moments of the intensity of L-look data (Jakeman & Pusey 1976; Oliver &
// Quegan, "Understanding SAR Images", ch. 7): for I = tau s, tau ~
// Gamma(nu, 1/nu), s ~ Gamma(L, 1/L), E[I^2]/E[I]^2 = (1 + 1/L)(1 + 1/nu).
// Returns +infinity when the ratio is at or below the speckle-only value.
double k_shape_moments(double m1, double m2, double looks);

}  // namespace ris
