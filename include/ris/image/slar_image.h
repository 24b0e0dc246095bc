// SLAR image formation: the geometry's elements summed into slant-range bins
// and azimuth lines with the radar equation (MODEL.md section 3).
//
// Each visible element returns
//   P_i = P_t G^2(beta) lambda^2 sigma0(theta_l) A_i / ((4 pi)^3 R^4),
// G = peak gain x one-way elevation gain at the look angle beta from nadir.
// Range: an element spreads its power over its own slant-range span, half
// from its near end to its centre and half from its centre to its far end
// (SlarGeometry::range_near_end_m / range_far_end_m), split among the bins it
// overlaps (bin k: R_near + k dr <= R < R_near + (k+1) dr); a facet seen at
// normal incidence (zero span) puts everything in one bin. This makes a
// flat plane's pixel follow sigma0 w dr / sin(theta) exactly, where hard
// binning of element centres would add a +-1 element (~10%) ripple.
// Azimuth (SLAR, real aperture): a pixel on line s_k sums the elements with
// |s - s_k| <= w(R)/2, w = R phi at the bin centre, each line standing for
// the strip [s - ds/2, s + ds/2] and counted by its overlap with the footprint
// (a running sum over lines per bin, so the cost does not grow with w).
// SAR and PPI: a window of constant width in lines replaces w(R)
// (SlarImagingParams::azimuth_window_lines).
//
// The result is plain data: mean power before speckle, a pixel mask, and the
// per-line counts behind the seed's shadow map.
//
// Example:
//   ris::SlarImagingParams p{bins, radar.transmit_power_w, radar.wavelength_m(),
//                            radar.peak_gain, radar.azimuth_beamwidth_rad, gain_fn};
//   ris::SlarImage img = ris::form_slar_image(geometry, lut, p, radar.source_file);
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/geometry/slant_range_bins.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/util/default_init_allocator.h"
#include "ris/util/units.h"

namespace ris {

// A point scatterer seen on one geometry line (ris/sim/point_target.h
// resolves and checks them): it adds P = P_t G^2 lambda^2 rcs / ((4 pi)^3 R^4)
// to that line's range profile at slant range R, like a ground element.
struct PointReturn {
  int line = 0;
  double along_m =
      0.0;  // exact along-track position (SAR) or azimuth (PPI, rad) on the line's axis
  double slant_range_m = 0.0;
  double look_rad = 0.0;  // look angle from nadir, for the elevation gain
  double rcs_m2 = 0.0;
  std::size_t target = 0;  // index of its target in the run's list (SAR/SLAR lines)
};

struct SlarImagingParams {
  SlantRangeBins range;
  double transmit_power_w = 0.0;       // P_t
  double wavelength_m = 0.0;           // lambda
  double peak_gain = 1.0;              // one-way boresight gain, linear
  double azimuth_beamwidth_rad = 0.0;  // phi: footprint w(R) = R phi
  // One-way elevation power gain relative to boresight at look angle beta
  // (radians from nadir); tabulated once at 0.01 deg, never called per sample.
  // Empty: uniform (1).
  std::function<double(double)> elevation_gain;
  // SAR and PPI (0: SLAR's w(R) = R phi): the azimuth window in lines, the
  // same at every range: SAR L_a rho_a / line spacing, PPI beamwidth / ray
  // spacing (the rays' "line spacing" is an angle).
  double azimuth_window_lines = 0.0;
  // SAR (0: one bin): the range window in bins, when the (multilooked) range
  // resolution differs from the sampling: a box L_r rho_r / dr bins wide
  // centred on each bin. The pixel mask stays per sampling bin.
  double range_window_bins = 0.0;
  // Point scatterers, added to their line's range profile.
  std::span<const PointReturn> point_returns;
  // Keep each visible element's power P_i (SlarImage::element_power_w), for
  // the coherent SAR (ris/sim/sar_coherent.h).
  bool keep_element_power = false;
};

// Slant-range pixel mask bits.
namespace pixel_flag {
inline constexpr std::uint8_t kShadow = 1;   // scene maps here but nothing is visible
inline constexpr std::uint8_t kLayover = 2;  // a visible layover element contributes
inline constexpr std::uint8_t kNoData = 4;   // no part of the scene (with data) maps here
}  // namespace pixel_flag

struct SlarImage {
  int lines = 0;  // rows, track start first
  int bins = 0;   // columns, near range first
  SlantRangeBins range;
  double line_spacing_m = 0.0;
  UninitVector<float> mean_power_w;  // lines x bins, received mean power (W)
  // lines x bins: true area (m^2) of the visible elements summed like the
  // power (for the area switch of equation 15, ris/image/greytone_terms.h).
  UninitVector<float> area_m2;
  UninitVector<std::uint8_t> mask;  // lines x bins, pixel_flag bits
  // Per line (not integrated over the footprint), by element centre:
  UninitVector<std::uint16_t> mapped_count;   // elements with data
  UninitVector<std::uint16_t> visible_count;  // of which visible (lit, facing)
  std::int64_t samples_in_swath = 0;          // elements with data whose centre is in a bin
  // Only with keep_element_power: geometry lines x samples, P_i of each
  // visible element (0 otherwise), W.
  std::vector<float> element_power_w;
  // Per point return (same order), the power it added, W.
  std::vector<double> point_power_w;

  std::size_t index(int line, int bin) const {
    return static_cast<std::size_t>(line) * static_cast<std::size_t>(bins) +
           static_cast<std::size_t>(bin);
  }
};

// Forms the image. Throws InputError naming radar_file when the swath misses
// every scene sample with data (key "sweep_delay"), and when a visible element's
// category is not in the lut (key "category").
SlarImage form_slar_image(const SlarGeometry& geometry, const Sigma0Lut& lut,
                          const SlarImagingParams& params, const std::string& radar_file);

// Per-line range profiles before azimuth integration: what image formation
// accumulates line by line (each line's elements spread over range bins), so
// a fused or streamed pipeline (ris/sim/slar_line_blocks.h) can fill them a
// block of lines at a time and share the azimuth step. All lines x bins.
struct SlarLineProfiles {
  int line0 = 0;  // the first line held (a block of a streamed image)
  int lines = 0;
  int bins = 0;
  UninitVector<float> power_w;                // per line, summed P_i spread over bins
  UninitVector<float> area_m2;                // per line, summed visible area
  UninitVector<std::uint8_t> touch;           // slar_touch bits
  UninitVector<std::uint16_t> mapped_count;   // as SlarImage
  UninitVector<std::uint16_t> visible_count;  // as SlarImage
  std::int64_t samples_in_swath = 0;

  // Lines [first_line, first_line + lines_) of bins_ bins each: touch and
  // the counts zeroed; power_w and area_m2 not set (UninitVector): the
  // caller writes every line's power and area in full (image formation does).
  void allocate(int lines_, int bins_, int first_line = 0);
  // line: the image's line number, in [line0, line0 + lines).
  std::size_t index(int line, int bin) const {
    return static_cast<std::size_t>(line - line0) * static_cast<std::size_t>(bins) +
           static_cast<std::size_t>(bin);
  }
};

// Which kinds of element touch a (line, bin) of SlarLineProfiles::touch.
namespace slar_touch {
inline constexpr std::uint8_t kData = 1;
inline constexpr std::uint8_t kVisible = 2;
inline constexpr std::uint8_t kLayover = 4;
}  // namespace slar_touch

// Two-way gain G^2 = (peak x G_e(beta))^2 tabulated over beta in [0, 90 deg]
// at 0.01 deg, linear interpolation; uniform() when the pattern is uniform
// (the caller may then skip the look angle).
class TwoWayGainTable {
 public:
  static constexpr int kSteps = 9000;
  static constexpr double kStepRad = (kPi / 2.0) / kSteps;
  static constexpr double kInvStepRad = kSteps / (kPi / 2.0);

  TwoWayGainTable(const std::function<double(double)>& relative_gain, double peak_gain,
                  const std::string& radar_file);
  bool uniform() const { return uniform_; }
  double at(double beta_rad) const { return interpolate(table_.data(), beta_rad); }
  // at() on the table data() (kSteps + 1 values), for a vectorised loop
  // that hoists the table's address.
  const double* data() const { return table_.data(); }
  static double interpolate(const double* table, double beta_rad) {
    // Times the reciprocal step, not divided by the step: a division per
    // element was a third of the power pass (the table index differs from
    // beta / step by at most an ulp).
    // Selects rather than std::clamp: a loop of lookups then vectorises.
    double pos = beta_rad * kInvStepRad;
    pos = pos < 0.0 ? 0.0 : pos;
    pos = pos > double(kSteps) ? double(kSteps) : pos;
    int i = static_cast<int>(pos);
    i = i < kSteps - 1 ? i : kSteps - 1;
    const double f = pos - i;
    return table[i] + f * (table[i + 1] - table[i]);
  }

 private:
  std::vector<double> table_;
  bool uniform_ = false;
};

// One line's per-element accumulation state (per-thread scratch, allocated
// once per thread).
struct SlarLineAccumulator {
  std::vector<double> acc, acc_area;
  std::vector<double> cum, cum_area;  // range-window running sums (bins + 1)
  explicit SlarLineAccumulator(int bins)
      : acc(static_cast<std::size_t>(bins)),
        acc_area(static_cast<std::size_t>(bins)),
        cum(static_cast<std::size_t>(bins) + 1),
        cum_area(static_cast<std::size_t>(bins) + 1) {}
  // SAR (SlarImagingParams::range_window_bins > 0): replaces the line's
  // bin-wise profile by its integral over [centre - W/2, centre + W/2] (bin
  // units) around each bin centre, the range resolution cell.
  void apply_range_window(double window_bins);
};

// The azimuth step of form_slar_image: integrates the profiles over each
// pixel's footprint w(R) = R phi (running sums over lines) into `img`
// (mean_power_w, area_m2, mask; img.lines/bins/range already set).
void integrate_slar_azimuth(const SlarLineProfiles& profiles, const SlarImagingParams& params,
                            double line_spacing_m, SlarImage& img);

// The SLAR azimuth footprint w(R) = R phi, metres.
inline double slar_footprint_m(double slant_range_m, double azimuth_beamwidth_rad) {
  return slant_range_m * azimuth_beamwidth_rad;
}

}  // namespace ris
