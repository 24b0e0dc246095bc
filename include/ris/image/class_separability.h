// Per-category statistics of an image in dB and the separability of
// category pairs (docs/quality.md): what the seed's interpreters judged by
// eye (can wheat be told from corn at this band?), as numbers.
//
// Each category's pixels (usable ones, ris/image/speckle_statistics.h) give
// the mean and standard deviation of 10 log10(I), and the dB of the mean
// intensity. A pair (a, b) is scored, with both classes taken as Gaussian in
// dB (Richards & Jia, Remote Sensing Digital Image Analysis, 4th ed. 2006,
// section 10.9):
//   contrast      mu_a - mu_b (dB of the mean intensities)
//   Bhattacharyya B = (mu_a - mu_b)^2 / (4 (s_a^2 + s_b^2))
//                     + 1/2 ln((s_a^2 + s_b^2) / (2 s_a s_b))   (means and
//                     spreads of the dB values)
//   Jeffries-Matusita JM = 2 (1 - exp(-B)), from 0 (the same law) to 2
//                     (fully separable); 1.9 is the usual "separable" mark.
//
// Example:
//   std::vector<ris::CategoryStatistics> c = ris::category_statistics(img, categories);
//   ris::Separability s = ris::separability(c[0], c[1]);
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ris/image/speckle_statistics.h"

namespace ris {

struct CategoryStatistics {
  std::int64_t category = 0;
  std::int64_t pixels = 0;
  double mean_db = 0.0;            // mean of 10 log10(I)
  double std_db = 0.0;             // their standard deviation
  double mean_intensity_db = 0.0;  // 10 log10 of the mean of I
};

// categories: same size as the image; pixels whose category is negative or
// not finite are left out. Sorted by category; categories with fewer than 2
// usable pixels are left out.
std::vector<CategoryStatistics> category_statistics(const IntensityView& img,
                                                    std::span<const double> categories);

struct Separability {
  std::int64_t a = 0, b = 0;
  double contrast_db = 0.0;
  double bhattacharyya = 0.0;
  double jeffries_matusita = 0.0;
};
Separability separability(const CategoryStatistics& a, const CategoryStatistics& b);

}  // namespace ris
