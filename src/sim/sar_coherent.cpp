#include "ris/sim/sar_coherent.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <utility>
#include <vector>

#include "ris/image/greytone_terms.h"
#include "ris/util/counter_rng.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

constexpr std::uint32_t kPhaseStream = 0x50484100u;  // "PHA\0" + look
constexpr std::uint32_t kNoiseStream = 0x4E4F4900u;  // "NOI\0" + look

// sinc(x) = sin(pi x) / (pi x) for |x| in [0, kSincSupportNulls], tabulated
// (linear interpolation; error below 2e-7 at 4096 steps per null spacing).
class SincTable {
 public:
  static constexpr int kPerUnit = 4096;
  SincTable() {
    const int n = kSincSupportNulls * kPerUnit;
    table_.resize(static_cast<std::size_t>(n) + 2);
    for (int i = 0; i <= n + 1; ++i) {
      const double x = double(i) / kPerUnit;
      table_[static_cast<std::size_t>(i)] = i == 0 ? 1.0 : std::sin(kPi * x) / (kPi * x);
    }
    // Energy inside the truncation, by the trapezoid rule on the table:
    // T = int_{-K}^{K} sinc^2 / int sinc^2 (the untruncated integral is 1).
    double e = 0.0;
    for (int i = 0; i < n; ++i) {
      const double a = table_[static_cast<std::size_t>(i)],
                   b = table_[static_cast<std::size_t>(i) + 1];
      e += 0.5 * (a * a + b * b) / kPerUnit;
    }
    energy_fraction_ = 2.0 * e;
  }
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

 private:
  std::vector<double> table_;
  double energy_fraction_ = 1.0;
};

// exp(j theta) for a phase that may be millions of radians (4 pi R / lambda).
std::complex<double> unit_phasor(double theta) {
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

  CoherentResponse(const SincTable& table, const SlarImage& img, const RadarParams& radar)
      : sinc(table),
        near(img.range.near_m),
        dr(img.range.bin_m),
        ds(img.line_spacing_m),
        k4pi_lambda(4.0 * kPi / radar.wavelength_m()),
        amp(kSincHalfPowerWidth / table.energy_fraction()),
        amp_r(std::sqrt(amp)),
        kx_r(kSincHalfPowerWidth / radar.sar.range_resolution_looks_m()),
        kx_a(kSincHalfPowerWidth / radar.sar.azimuth_resolution_looks_m()),
        support_r_m(kSincSupportNulls / kx_r),
        support_a(static_cast<int>(std::floor(kSincSupportNulls / (kx_a * ds)))) {
    kernel_a.resize(static_cast<std::size_t>(2 * support_a + 1));
    for (int m = -support_a; m <= support_a; ++m)
      kernel_a[static_cast<std::size_t>(m + support_a)] = std::sqrt(amp) * sinc(m * ds * kx_a);
  }
  // The bins [b0, b1] within the range support of slant range R.
  std::pair<int, int> bins_near(double R, int bins) const {
    const int b0 = std::max(0, static_cast<int>(std::ceil((R - support_r_m - near) / dr - 0.5)));
    const int b1 =
        std::min(bins - 1, static_cast<int>(std::floor((R + support_r_m - near) / dr - 0.5)));
    return {b0, b1};
  }
};

// Range compression: each geometry line into its row of bins, every
// element a circular Gaussian reflectivity with E|a|^2 = P_i (see the
// header) at its two-way phase.
void range_compress(const SlarSimulation& sim, const CoherentResponse& h, std::uint64_t seed,
                    std::uint32_t phase_stream, std::vector<std::complex<float>>& range_lines) {
  const SlarGeometry& g = sim.geometry;
  const SlarImage& img = sim.image;
  const int lines = img.lines, bins = img.bins;
#pragma omp parallel for schedule(dynamic, 8)
  for (int line = 0; line < lines; ++line) {
    std::complex<float>* row = range_lines.data() + img.index(line, 0);
    std::fill(row, row + bins, std::complex<float>(0.0f, 0.0f));
    for (int j = 0; j < g.samples; ++j) {
      const std::size_t i = g.index(line, j);
      const float p = img.element_power_w[i];
      if (!(p > 0.0f)) continue;
      const double R = g.slant_range_m[i];
      const auto [b0, b1] = h.bins_near(R, bins);
      if (b0 > b1) continue;
      CounterRng rng(seed, static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(line),
                     phase_stream);
      const double re = rng.normal(), im = rng.normal();
      const std::complex<double> a = std::sqrt(0.5 * double(p)) * h.amp_r *
                                     std::complex<double>(re, im) * unit_phasor(-h.k4pi_lambda * R);
      for (int b = b0; b <= b1; ++b) {
        const double d = R - (h.near + (b + 0.5) * h.dr);
        row[b] += std::complex<float>(a * h.sinc(d * h.kx_r));
      }
    }
  }
}

// Azimuth compression along each bin, then thermal noise.
void azimuth_compress(const SlarSimulation& sim, const CoherentResponse& h, std::uint64_t seed,
                      std::uint32_t noise_stream,
                      const std::vector<std::complex<float>>& range_lines,
                      std::vector<std::complex<float>>& z) {
  const SlarImage& img = sim.image;
  const int lines = img.lines, bins = img.bins, support_a = h.support_a;
#pragma omp parallel for schedule(static)
  for (int k = 0; k < lines; ++k) {
    const int m0 = std::max(-support_a, -k), m1 = std::min(support_a, lines - 1 - k);
    for (int b = 0; b < bins; ++b) {
      std::complex<double> acc(0.0, 0.0);
      for (int m = m0; m <= m1; ++m) {
        acc += std::complex<double>(range_lines[img.index(k + m, b)]) *
               h.kernel_a[static_cast<std::size_t>(m + support_a)];
      }
      if (!sim.noise_power_w.empty()) {
        CounterRng rng(seed, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(k),
                       noise_stream);
        const double sigma = std::sqrt(0.5 * sim.noise_power_w[static_cast<std::size_t>(b)]);
        const double re = rng.normal(), im = rng.normal();
        acc += std::complex<double>(sigma * re, sigma * im);
      }
      z[img.index(k, b)] = std::complex<float>(acc);
    }
  }
}

// Point targets at their exact position, phase 0 plus the two-way phase.
void add_point_targets(const SlarSimulation& sim, const CoherentResponse& h,
                       std::vector<std::complex<float>>& z) {
  const SlarImage& img = sim.image;
  const int lines = img.lines, bins = img.bins;
  for (std::size_t t = 0; t < sim.point_returns.size(); ++t) {
    const PointReturn& pr = sim.point_returns[t];
    const double R = pr.slant_range_m;
    const std::complex<double> a =
        std::sqrt(img.point_power_w[t]) * h.amp * unit_phasor(-h.k4pi_lambda * R);
    const auto [b0, b1] = h.bins_near(R, bins);
    const double support_s_m = kSincSupportNulls / h.kx_a;
    const int k0 =
        std::max(0, static_cast<int>(std::ceil((pr.along_m - support_s_m) / h.ds - 0.5)));
    const int k1 =
        std::min(lines - 1, static_cast<int>(std::floor((pr.along_m + support_s_m) / h.ds - 0.5)));
    for (int k = k0; k <= k1; ++k) {
      const double ha = h.sinc((pr.along_m - (k + 0.5) * h.ds) * h.kx_a);
      for (int b = b0; b <= b1; ++b) {
        const double hr = h.sinc((R - (h.near + (b + 0.5) * h.dr)) * h.kx_r);
        z[img.index(k, b)] += std::complex<float>(a * (ha * hr));
      }
    }
  }
}

}  // namespace

std::vector<float> coherent_sar_intensity(const SlarSimulation& sim, std::uint64_t seed) {
  const SlarGeometry& g = sim.geometry;
  const SlarImage& img = sim.image;
  const RadarParams& radar = sim.radar;
  RIS_CHECK(radar.mode == RadarMode::sar);
  RIS_CHECK(img.element_power_w.size() == g.flags.size());
  RIS_CHECK(img.lines == g.lines);
  const int lines = img.lines, bins = img.bins;
  const std::size_t n_pix = static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins);
  const int looks = radar.sar.range_looks * radar.sar.azimuth_looks;
  static const SincTable sinc;
  const CoherentResponse h(sinc, img, radar);
  // The range and area switches, as the mean image had them applied.
  const SwitchedRadarTerms terms = switched_terms(radar);

  std::vector<std::complex<float>> range_lines(n_pix);
  std::vector<std::complex<float>> z(n_pix);
  std::vector<double> intensity(n_pix, 0.0);
  for (int look = 0; look < looks; ++look) {
    range_compress(sim, h, seed, kPhaseStream + static_cast<std::uint32_t>(look), range_lines);
    azimuth_compress(sim, h, seed, kNoiseStream + static_cast<std::uint32_t>(look), range_lines, z);
    add_point_targets(sim, h, z);
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n_pix; ++i) intensity[i] += double(std::norm(z[i])) / looks;
  }

  std::vector<float> out(n_pix);
#pragma omp parallel for schedule(static)
  for (int k = 0; k < lines; ++k) {
    for (int b = 0; b < bins; ++b) {
      const std::size_t i = img.index(k, b);
      if (img.mask[i] & pixel_flag::kNoData) {
        out[i] = std::numeric_limits<float>::quiet_NaN();
        continue;
      }
      const double f =
          range_correction(terms, img.range.centre_m(b)) * area_correction(terms, img.area_m2[i]);
      out[i] = static_cast<float>(intensity[i] * f);
    }
  }
  return out;
}

}  // namespace ris
