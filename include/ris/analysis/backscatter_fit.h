// Fitting each category's sigma0(theta) from a calibrated image (issue 34
// item 4, `ris calibrate`, docs/calibrate.md): the inverse of the
// simulation's lookup of sigma0 by category and local incidence.
//
// Per category, the pixels are binned by local incidence (bins of
// `bin_deg`, bin k = [k w, (k + 1) w)); in each bin the estimate is the
// mean of the LINEAR sigma0, because speckle is multiplicative with mean 1
// (MODEL.md section 3, "Fading": unit-mean gamma law of N-look intensity), so the mean of linear
// intensity is unbiased where the mean of dB is not (single-look speckle
// puts the mean of 10 log10 I 2.51 dB below 10 log10 E[I]: the Euler-gamma
// bias, 10 log10(e) x 0.5772). The bin's angle is its pixels' mean
// incidence, not the bin centre, so a bin filled unevenly does not move the
// curve along its slope. Bins with fewer than `min_bin_pixels` pixels are
// dropped.
//
// The fitted curve is the table form ris reads (docs/backscatter.md,
// "Measured tables"): sigma0 in dB at the kept bins' angles, linear in dB
// between them, so the written library is exactly what a simulation then
// uses. The spread reported per category:
//   - per bin: pixels, the pixels' coefficient of variation s / m (speckle
//     alone: 1 / sqrt(L) for L looks), and the standard error of the bin's
//     dB value, (10 / ln 10) s / (m sqrt n) (the delta method);
//   - over the bins: a weighted least-squares quadratic in theta (dB =
//     c0 + c1 t + c2 t^2, t in degrees, weights n), its coefficients and the
//     rms and largest residual of the bins about it (dB): how far the table
//     departs from a smooth curve, i.e. texture, mixed pixels or noise the
//     bins did not average out. With FitForm::quadratic the table is this
//     quadratic at the bins' angles instead of the bin means.
//
// Example:
//   ris::BackscatterFitOptions o;            // 1 deg bins, >= 50 pixels a bin
//   std::vector<ris::CategoryFit> fits = ris::fit_backscatter(sigma0, incidence_deg, category, o);
//   std::string csv = ris::backscatter_table_csv(fits, band, names, "ris calibrate ...");
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "ris/backscatter/polarisation.h"

namespace ris {

enum class FitForm { table, quadratic };

struct BackscatterFitOptions {
  double bin_deg = 1.0;
  std::int64_t min_bin_pixels = 50;        // a bin with fewer is dropped
  std::int64_t min_category_pixels = 500;  // a category with fewer (in kept bins) is not fitted
  int min_bins = 3;                        // ... nor one with fewer kept bins
  FitForm form = FitForm::table;
};

struct IncidenceBinFit {
  double angle_deg = 0.0;  // the pixels' mean local incidence
  std::int64_t pixels = 0;
  double mean_linear = 0.0;  // mean sigma0 (m^2/m^2)
  double cv = 0.0;           // s / m of the pixels
  double se_db = 0.0;        // standard error of 10 log10(mean)
  double residual_db = 0.0;  // bin dB minus the quadratic at angle_deg
  double table_db = 0.0;     // the value written: bin dB (table) or quadratic
};

struct CategoryFit {
  std::int32_t category = 0;
  std::int64_t pixels = 0;       // pixels of the category with a valid sample
  std::int64_t used_pixels = 0;  // in the kept bins
  std::vector<IncidenceBinFit> bins;
  double quad[3] = {0.0, 0.0, 0.0};  // dB = quad[0] + quad[1] t + quad[2] t^2 (t in deg)
  double rms_residual_db = 0.0;      // pixel-weighted rms of the bins about the quadratic
  double max_residual_db = 0.0;
  double median_se_db = 0.0;
  bool fitted = false;  // false: too few pixels or bins (why: `reason`)
  std::string reason;
};

// sigma0 (linear, > 0 and finite to count), incidence_deg (0..90 to count)
// and category (< 0: excluded) per pixel, all the same size. One entry per
// category present (sorted by id), fitted or not. Throws
// std::invalid_argument for sizes that differ or bad options.
std::vector<CategoryFit> fit_backscatter(std::span<const float> sigma0_linear,
                                         std::span<const float> incidence_deg,
                                         std::span<const std::int32_t> category,
                                         const BackscatterFitOptions& options);

// The fitted categories as a sigma0 table (docs/backscatter.md, "Measured
// tables"): header comments (provenance, `# clamp: <clamp>`, one
// `# category N: name` line each), then one curve per category at `band`.
// name_of(id) gives the display name ("" for none).
std::string backscatter_table_csv(const std::vector<CategoryFit>& fits, const RadarBand& band,
                                  const std::function<std::string(std::int32_t)>& name_of,
                                  const std::string& provenance, bool clamp);

// The same table's "# category N: name" lines and rows alone, to append to
// an existing table (another band or polarisation of the same categories).
std::string backscatter_table_rows(const std::vector<CategoryFit>& fits, const RadarBand& band,
                                   const std::function<std::string(std::int32_t)>& name_of);

}  // namespace ris
