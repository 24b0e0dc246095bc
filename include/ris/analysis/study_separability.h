// Separability of backscatter categories at matched geometry (issue 36): the
// frequency/polarisation study's measure of how well a band tells the
// scene's categories apart.
//
// Categories are compared only where the comparison is fair, pixel by pixel:
//
//   1. Calibrated sigma0. A pixel's mean power P is the sum over its elements
//      of K_i sigma0_i; the pixel's radar-equation factor F = sum K_i is the
//      mean power the same radar receives there when every element has
//      sigma0 = 1 (a run with UniformSigma0). I / F, with I the pixel's
//      speckled power, is its calibrated sigma0: range, area, antenna and
//      elevation-pattern factors cancel; on a pure pixel (one category)
//      E[I / F] = sigma0 of the category at the pixel's local incidence.
//   2. Matched geometry. A pixel enters the comparison when its range bin
//      lies inside the chosen range interval (a fraction of the swath, e.g.
//      the seed's "middle third") and every element contributing to it has
//      its local incidence within one incidence bin (`incidence_bin_rad`
//      wide); pairs are compared within each incidence bin, at one
//      incidence: each category's mean is moved to the pair's mean incidence
//      along the bin's common trend (the pooled within-category slope of
//      I / m on incidence, an analysis of covariance), so that categories
//      at the two edges of a bin are not told apart by the slope of one law.
//   3. Speckle at the radar's number of looks L (the image's N per range
//      bin): a category's calibrated intensity in a bin is Gamma(L, m / L)
//      with m its mean. For two such laws the Bhattacharyya distance has the
//      closed form
//          B = L ln((m_a + m_b) / (2 sqrt(m_a m_b)))
//      (integral of sqrt(p_a p_b) over x of two gamma densities of equal
//      shape L; Kailath 1967, IEEE Trans. Commun. Technol. 15(1), for the
//      definition), and the Jeffries-Matusita distance JM = 2 (1 - e^-B),
//      0 (same law) to 2 (separable; 1.9 the usual mark), as ris quality
//      (ris/image/class_separability.h) but for the gamma laws of speckle.
//   4. Sampling error. m is estimated from n pixels: ln m has standard error
//      s / (m sqrt n) (s the pixels' standard deviation: speckle and any
//      variation left inside the bin). Per bin z = ln(m_a / m_b) / sigma,
//      sigma^2 the sum of both squared errors and the slope's variance times
//      the squared difference of the categories' mean incidence; over the interval the bins'
//      log ratios are combined with inverse-variance weights into Z. A pair
//      is separated when |Z| > z_critical (run_study: a Bonferroni bound over
//      every pair and band, family error 1 %); otherwise its difference is
//      zero within its sampling error. `jm_noise` is the JM a log ratio of
//      one standard error would give: the noise level of `jm`.
//   5. Summary. A pair's JM over the interval is the mean of its bins' JM,
//      weighted by n_a n_b / (n_a + n_b); a band's score is the mean over
//      pairs of JM counting only separated pairs (the average pairwise
//      separability used for feature selection, Swain & Davis 1978, Remote
//      Sensing: The Quantitative Approach, ch. 3). The best band has the
//      largest score; when no pair is separated in any band, there is none
//      ("no band separates these categories").
//
// This is one band's measure from one band's run; a run that produces N
// channels at once (issue 31) can call band_separability per channel with
// the same PixelAttribution and incidence bins.
//
// Example:
//   PixelAttribution at = attribute_pixels(sim);            // keep_geometry
//   IncidenceBins ib = incidence_bins(sim, at, window);
//   BandSeparability s = band_separability(at.category, ib, calibrated, looks,
//                                          categories, {z_critical});
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

// The closed forms of point 3. looks > 0, means > 0.
double gamma_bhattacharyya(double mean_a, double mean_b, double looks);
double jeffries_matusita(double bhattacharyya);
// The quantile z with P(|N(0,1)| > z) = two_sided_p (0 < p < 1).
double normal_two_sided_quantile(double two_sided_p);

// Per slant-range pixel: the category every contributing element has (or
// -1), and the lowest and highest local incidence (rad) among those elements
// (NaN when not attributed). See study.h for which elements contribute.
// sim must keep its per-sample geometry (SlarOptions::keep_geometry).
struct PixelAttribution {
  std::vector<std::int32_t> category;  // lines x bins
  std::vector<float> incidence_lo_rad;
  std::vector<float> incidence_hi_rad;
};
PixelAttribution attribute_pixels(const SlarSimulation& sim);

struct StudyWindow {
  // The range interval as fractions of the image's slant-range extent
  // (0 = near edge, 1 = far edge); a pixel's range-bin centre must lie in it.
  double range_lo_fraction = 0.0;
  double range_hi_fraction = 1.0;
  double incidence_bin_rad = 0.017453292519943295;  // 1 deg
};

struct IncidenceBins {
  std::vector<std::int32_t> bin;     // per pixel, or -1 (outside the window, mixed incidence)
  std::vector<float> incidence_rad;  // per pixel: the middle of its contributors' span
  int count = 0;
  double first_lo_rad = 0.0;  // bin k covers [first + k w, first + (k + 1) w)
  double width_rad = 0.0;
  double range_lo_m = 0.0, range_hi_m = 0.0;  // the window in slant range
};
IncidenceBins incidence_bins(const SlarSimulation& sim, const PixelAttribution& at,
                             const StudyWindow& window);

struct SeparabilityOptions {
  double z_critical = 3.0;
  std::int64_t min_pixels = 20;  // per category and bin, for the bin to count
};

// One pair in one incidence bin.
struct PairBin {
  int bin = 0;
  std::uint16_t a = 0, b = 0;
  std::int64_t pixels_a = 0, pixels_b = 0;
  double mean_a = 0.0, mean_b = 0.0;  // calibrated sigma0 (linear) at the pair's mean incidence
  double looks = 0.0;
  double sigma_log = 0.0;  // standard error of ln(mean_a / mean_b)
  double z = 0.0, jm = 0.0, jm_noise = 0.0;
};

// One pair over the window.
struct PairSeparability {
  std::uint16_t a = 0, b = 0;  // a < b
  int bins = 0;                // bins where both have min_pixels
  double delta_db = 0.0;       // 10 log10(m_a / m_b), combined over bins (NaN: no bin)
  double z = 0.0;
  double jm = 0.0, jm_noise = 0.0;
  bool separated = false;
};

struct BandSeparability {
  std::vector<PairBin> bins;
  std::vector<PairSeparability> pairs;  // every a < b of `categories`
  int compared_pairs = 0;               // pairs with at least one bin
  int separated_pairs = 0;
  double score = 0.0;   // mean over compared pairs of jm x separated
  double min_jm = 0.0;  // over compared pairs (NaN: none)
  double max_abs_z = 0.0;
};

// calibrated: I / F per pixel; looks: L per pixel (both lines x bins).
BandSeparability band_separability(std::span<const std::int32_t> labels, const IncidenceBins& ib,
                                   std::span<const double> calibrated,
                                   std::span<const double> looks,
                                   const std::vector<std::uint16_t>& categories,
                                   const SeparabilityOptions& options);

// A source that gives every category of `names` the same law: sigma0 = 1
// (law empty: the radar-equation factor run) or law(incidence, band). Names,
// ids and colours are those of `names`.
class UniformSigma0 final : public Sigma0Source {
 public:
  using Law = double (*)(double incidence_rad);
  UniformSigma0(const Sigma0Source& names, Law law, std::string description)
      : names_(names), law_(law), description_(std::move(description)) {}
  bool has_category(std::uint16_t c) const override { return names_.has_category(c); }
  double sigma0(std::uint16_t, double incidence_rad, const RadarBand&) const override {
    return law_ == nullptr ? 1.0 : law_(incidence_rad);
  }
  std::string category_name(std::uint16_t c) const override { return names_.category_name(c); }
  std::string description() const override { return description_; }
  std::vector<std::uint16_t> category_ids() const override { return names_.category_ids(); }

 private:
  const Sigma0Source& names_;
  Law law_;
  std::string description_;
};

// Muhleman's law 0.0118 cos t / (sin t + 0.111 cos t)^3 (MODEL.md section 4),
// the null check's one backscatter for every category.
double muhleman_sigma0(double incidence_rad);

}  // namespace ris
