// Internal: the coherent SAR's pieces (ris/sim/sar_coherent.h, where the
// physics and the formulas are described), shared by the in-memory run
// (coherent_sar_intensity, src/sim/modes/sar_coherent.cpp) and the streamed one
// (src/sim/stream/sar_coherent_stream.h), so that both run the same arithmetic in
// the same order and give the same bytes: the sinc table, the compressed
// impulse responses, and range compression, azimuth compression, point
// targets and the final corrections one image line at a time. Every random
// number is keyed by (seed, sample or bin, line, look) (CounterRng), never
// by a running generator, so a line's values do not depend on which block,
// thread or rank computes it.
#pragma once

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdint>
#include <utility>
#include <vector>

#include "ris/image/greytone_terms.h"
#include "ris/image/slar_image.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/sar_coherent.h"
#include "ris/util/units.h"

namespace ris::detail {

inline constexpr std::uint32_t kCoherentPhaseStream = 0x50484100u;  // "PHA\0" + look
inline constexpr std::uint32_t kCoherentNoiseStream = 0x4E4F4900u;  // "NOI\0" + look

// sinc(x) = sin(pi x) / (pi x) for |x| in [0, kSincSupportNulls], tabulated
// (linear interpolation; error below 2e-7 at 4096 steps per null spacing).
class SincTable {
 public:
  static constexpr int kPerUnit = 4096;
  SincTable();
  // |x| in null spacings; 0 beyond the support.
  double operator()(double x) const {
    const double pos = std::abs(x) * kPerUnit;
    if (!(pos < kSincSupportNulls * kPerUnit)) return 0.0;
    const int i = static_cast<int>(pos);
    const double f = pos - i;
    const double* t = table_.data() + i;
    return t[0] + f * (t[1] - t[0]);
  }
  double energy_fraction() const { return energy_fraction_; }
  // The one table of the process (built at first use).
  static const SincTable& shared();

 private:
  std::vector<double> table_;
  double energy_fraction_ = 1.0;
};

// exp(j theta) for a phase that may be millions of radians (4 pi R / lambda).
inline std::complex<double> unit_phasor(double theta) {
  const double t = std::remainder(theta, 2.0 * kPi);
  return {std::cos(t), std::sin(t)};
}

// The compression's fixed parts for a run: the sinc responses
// h(d) = A sinc(0.886 d / rho) in range and azimuth (x = d kappa / rho null
// spacings), their supports, and the azimuth kernel over line offsets.
struct CoherentResponse {
  const SincTable& sinc;
  double near, dr, ds;  // first bin's near edge, bin and line spacing (m)
  double k4pi_lambda;   // two-way phase per metre
  double amp;           // A^2 per dimension
  double amp_r;
  double kx_r, kx_a;   // null spacings per metre
  double support_r_m;  // metres of slant range each side
  int support_a;       // lines each side
  std::vector<double> kernel_a;

  CoherentResponse(const SincTable& table, const SlarImage& img, const RadarParams& radar);
  // The bins [b0, b1] within the range support of slant range R.
  std::pair<int, int> bins_near(double R, int bins) const {
    const int b0 = std::max(0, static_cast<int>(std::ceil((R - support_r_m - near) / dr - 0.5)));
    const int b1 =
        std::min(bins - 1, static_cast<int>(std::floor((R + support_r_m - near) / dr - 0.5)));
    return {b0, b1};
  }
  // The lines [k0, k1] a point at along-track position along_m reaches.
  std::pair<int, int> lines_near(double along_m, int lines) const;
};

// Range compression of geometry line `line` into its row of bins (`row`,
// bins long, overwritten): every element j with power P_j > 0 a circular
// Gaussian reflectivity with E|a|^2 = P_j at its two-way phase.
// element_power_w and slant_range_m: the line's samples.
void range_compress_line(const CoherentResponse& h, int line, int samples,
                         const float* element_power_w, const float* slant_range_m, int bins,
                         std::uint64_t seed, std::uint32_t phase_stream, std::complex<float>* row);

// Azimuth compression of image line k (of `lines`) along each bin, then
// thermal noise (noise_power_w per bin; empty: none) into z_row.
// range_lines: rows of range-compressed lines from line range_line0, holding
// every line within the kernel of k.
void azimuth_compress_line(const CoherentResponse& h, int k, int lines, int bins,
                           const std::complex<float>* range_lines, int range_line0,
                           const std::vector<double>& noise_power_w, std::uint64_t seed,
                           std::uint32_t noise_stream, std::complex<float>* z_row);

// A point target's response (phase 0 plus the two-way phase, power
// power_w) added to the lines it reaches within [k_lo, k_hi) of z, whose
// rows start at line z_line0.
void add_point_target(const CoherentResponse& h, const PointReturn& target, double power_w,
                      int lines, int bins, int k_lo, int k_hi, std::complex<float>* z, int z_line0);

// Image line k's intensity (the looks' mean, W) with the range and area
// switches applied as the mean image has them, NaN for no data.
void finish_coherent_line(const SwitchedRadarTerms& terms, const SlantRangeBins& range,
                          const double* intensity, const std::uint8_t* mask, const float* area_m2,
                          int bins, float* out);

}  // namespace ris::detail
