#pragma once

// Unsupervised land-cover classification of a multi-band raster (issue 34
// item 4, docs/classify.md): every band to dB, smoothed (OpenCV's Gaussian
// blur: the speckle of a single look has a dB spread of 5.6 dB), then
// k-means (k-means++ seeding from a seeded cv::RNG, several attempts) over
// the smoothed pixel vectors. Classes are numbered 1..K in increasing mean
// of the first band, so the numbering does not depend on k-means' order.
//
// Supervised (classify_nearest_mean): the same smoothed dB vectors, each
// pixel given the category whose training pixels' mean vector is nearest
// (Euclidean distance in dB; the minimum-distance classifier of Richards,
// "Remote Sensing Digital Image Analysis", 5th ed. 2013, section 8.4).
//
// No data: pixels whose `valid` entry is 0 are left out of the smoothing
// (normalised convolution: the blur of the valid dB values divided by the
// blur of the validity, Knutsson & Westin, "Normalized and differential
// convolution", CVPR 1993) and of the clustering, and get label 0.
#include <cstdint>
#include <span>
#include <vector>

namespace ris {

struct ClassifyRequest {
  int rows = 0, cols = 0;
  std::vector<std::vector<float>> bands;  // each rows*cols, linear power (> 0)
  int classes = 4;                        // K, 2..255
  double smooth_sigma_px = 1.0;           // Gaussian smoothing of the dB bands
  int attempts = 3;
  std::uint64_t seed = 1;
  std::vector<std::uint8_t> valid;  // rows*cols, 0 = no data; empty: every pixel has data
};

struct ClassifyResult {
  std::vector<std::uint8_t> labels;        // rows*cols: a class code, 0 where no data
  std::vector<std::uint8_t> codes;         // per class: its code (1..K unsupervised)
  std::vector<std::vector<double>> means;  // [class][band], dB, of the smoothed bands
  std::vector<std::size_t> pixels;         // per class
};

ClassifyResult classify_unsupervised(const ClassifyRequest& req);

// Supervised: `training` (rows*cols) holds a category code 1..255 on the
// training pixels, 0 elsewhere; req.classes is ignored (the classes are the
// codes present on valid pixels, in increasing code order). Throws
// std::invalid_argument when fewer than 2 codes have valid training pixels.
ClassifyResult classify_nearest_mean(const ClassifyRequest& req,
                                     std::span<const std::uint8_t> training);

// Per-class statistics of the unsmoothed linear bands over a labelling
// (ClassifyResult::labels): for each class, each band's mean intensity in
// dB (10 log10 of the mean of linear power, so not biased by the log) and
// its ENL = mean^2 / variance (unbiased variance; Oliver & Quegan 1998,
// section 4.4: 1 for single-look exponential speckle, L for L looks), and
// the moments k_shape_moments takes (mean and mean square, linear).
struct ClassStatistics {
  std::uint8_t code = 0;
  std::size_t pixels = 0;
  std::vector<double> mean_db, enl;  // per band
  std::vector<double> m1, m2;        // per band: E[I], E[I^2]
};
std::vector<ClassStatistics> class_statistics(const ClassifyRequest& req,
                                              const ClassifyResult& res);

// K-distribution shape nu by the method of moments from the first two
// moments of the intensity of L-look data (Jakeman & Pusey 1976; Oliver &
// Quegan, "Understanding SAR Images", ch. 7): for I = tau s, tau ~
// Gamma(nu, 1/nu), s ~ Gamma(L, 1/L), E[I^2]/E[I]^2 = (1 + 1/L)(1 + 1/nu).
// Returns +infinity when the ratio is at or below the speckle-only value.
double k_shape_moments(double m1, double m2, double looks);

}  // namespace ris
