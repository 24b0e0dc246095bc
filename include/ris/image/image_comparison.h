// How well one intensity image matches another of the same grid
// (docs/quality.md, "ris compare"): correlation of their dB values at
// several averaging windows, bias and RMS difference, per-category bias, the
// distance between their dB histograms, and the overlap of a simulation's
// shadow and layover masks with the dark and bright parts of the other image.
//
//   window w   the intensities averaged over non-overlapping w x w blocks
//              (only blocks whose pixels all hold data in both), then dB:
//              averaging removes speckle, so the correlation of the
//              underlying radiometry shows at w = 5 or 9
//   Pearson r  of the dB pairs; Spearman rho, Pearson of their ranks
//   bias       mean of (b - a) dB; RMS difference sqrt(mean (b - a)^2)
//   Hellinger  H = sqrt(1 - sum_k sqrt(p_k q_k)) over 1 dB bins of the two
//              images' pixel dB values (each histogram normalised on its
//              own): 0 the same distribution, 1 disjoint
//   IoU        |mask and dark| / |mask or dark|, where dark is where b,
//              averaged 5 x 5, is at or below its 10th percentile (and bright
//              at or above its 90th, against the layover mask)
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace ris {

struct WindowAgreement {
  int window = 1;
  std::int64_t blocks = 0;
  double pearson = 0.0, spearman = 0.0;
  double bias_db = 0.0, rms_db = 0.0;
};

// a, b: rows x cols intensities (NaN or <= 0: no data).
WindowAgreement window_agreement(std::span<const float> a, std::span<const float> b, int cols,
                                 int rows, int window);

double histogram_hellinger(std::span<const float> a, std::span<const float> b);

struct CategoryBias {
  std::int64_t category = 0;
  std::int64_t pixels = 0;
  double bias_db = 0.0;  // mean of (b - a) dB
};
std::vector<CategoryBias> category_bias(std::span<const float> a, std::span<const float> b,
                                        std::span<const double> categories);

struct MaskAgreement {
  std::int64_t mask_pixels = 0, image_pixels = 0;
  double iou = 0.0;
};
// mask: rows x cols bits; `bit` set where the simulation has shadow (1) or
// layover (2); dark = true compares with b's dark part, else its bright part.
MaskAgreement mask_agreement(std::span<const std::uint8_t> mask, std::uint8_t bit,
                             std::span<const float> b, int cols, int rows, bool dark);

}  // namespace ris
