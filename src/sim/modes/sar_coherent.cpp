#include "ris/sim/sar_coherent.h"

#include "sim/modes/sar_coherent_parts.h"

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

namespace detail {

SincTable::SincTable() {
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

const SincTable& SincTable::shared() {
  static const SincTable table;
  return table;
}

CoherentResponse::CoherentResponse(const SincTable& table, const SlarImage& img,
                                   const RadarParams& radar)
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

std::pair<int, int> CoherentResponse::lines_near(double along_m, int lines) const {
  const double support_s_m = kSincSupportNulls / kx_a;
  const int k0 = std::max(0, static_cast<int>(std::ceil((along_m - support_s_m) / ds - 0.5)));
  const int k1 =
      std::min(lines - 1, static_cast<int>(std::floor((along_m + support_s_m) / ds - 0.5)));
  return {k0, k1};
}

void range_compress_line(const CoherentResponse& h, int line, int samples,
                         const float* element_power_w, const float* slant_range_m, int bins,
                         std::uint64_t seed, std::uint32_t phase_stream, std::complex<float>* row) {
  std::fill(row, row + bins, std::complex<float>(0.0f, 0.0f));
  for (int j = 0; j < samples; ++j) {
    const float p = element_power_w[j];
    if (!(p > 0.0f)) continue;
    const double R = slant_range_m[j];
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

void azimuth_compress_line(const CoherentResponse& h, int k, int lines, int bins,
                           const std::complex<float>* range_lines, int range_line0,
                           const std::vector<double>& noise_power_w, std::uint64_t seed,
                           std::uint32_t noise_stream, std::complex<float>* z_row) {
  const int support_a = h.support_a;
  const int m0 = std::max(-support_a, -k), m1 = std::min(support_a, lines - 1 - k);
  const auto at = [&](int line, int b) {
    return static_cast<std::size_t>(line - range_line0) * static_cast<std::size_t>(bins) +
           static_cast<std::size_t>(b);
  };
  for (int b = 0; b < bins; ++b) {
    std::complex<double> acc(0.0, 0.0);
    for (int m = m0; m <= m1; ++m) {
      acc += std::complex<double>(range_lines[at(k + m, b)]) *
             h.kernel_a[static_cast<std::size_t>(m + support_a)];
    }
    if (!noise_power_w.empty()) {
      CounterRng rng(seed, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(k),
                     noise_stream);
      const double sigma = std::sqrt(0.5 * noise_power_w[static_cast<std::size_t>(b)]);
      const double re = rng.normal(), im = rng.normal();
      acc += std::complex<double>(sigma * re, sigma * im);
    }
    z_row[b] = std::complex<float>(acc);
  }
}

void add_point_target(const CoherentResponse& h, const PointReturn& pr, double power_w, int lines,
                      int bins, int k_lo, int k_hi, std::complex<float>* z, int z_line0) {
  const double R = pr.slant_range_m;
  const std::complex<double> a = std::sqrt(power_w) * h.amp * unit_phasor(-h.k4pi_lambda * R);
  const auto [b0, b1] = h.bins_near(R, bins);
  const auto [k0, k1] = h.lines_near(pr.along_m, lines);
  for (int k = std::max(k0, k_lo); k <= std::min(k1, k_hi - 1); ++k) {
    const double ha = h.sinc((pr.along_m - (k + 0.5) * h.ds) * h.kx_a);
    std::complex<float>* row =
        z + static_cast<std::size_t>(k - z_line0) * static_cast<std::size_t>(bins);
    for (int b = b0; b <= b1; ++b) {
      const double hr = h.sinc((R - (h.near + (b + 0.5) * h.dr)) * h.kx_r);
      row[b] += std::complex<float>(a * (ha * hr));
    }
  }
}

void finish_coherent_line(const SwitchedRadarTerms& terms, const SlantRangeBins& range,
                          const double* intensity, const std::uint8_t* mask, const float* area_m2,
                          int bins, float* out) {
  for (int b = 0; b < bins; ++b) {
    if (mask[b] & pixel_flag::kNoData) {
      out[b] = std::numeric_limits<float>::quiet_NaN();
      continue;
    }
    const double f =
        range_correction(terms, range.centre_m(b)) * area_correction(terms, area_m2[b]);
    out[b] = static_cast<float>(intensity[b] * f);
  }
}

}  // namespace detail

std::vector<float> coherent_sar_intensity(const SlarSimulation& sim, std::uint64_t seed) {
  using namespace detail;
  const SlarGeometry& g = sim.geometry;
  const SlarImage& img = sim.image;
  const RadarParams& radar = sim.radar;
  RIS_CHECK(radar.mode == RadarMode::sar);
  RIS_CHECK(img.element_power_w.size() == g.flags.size());
  RIS_CHECK(img.lines == g.lines);
  const int lines = img.lines, bins = img.bins;
  const std::size_t n_pix = static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins);
  const int looks = radar.sar.range_looks * radar.sar.azimuth_looks;
  const CoherentResponse h(SincTable::shared(), img, radar);
  // The range and area switches, as the mean image had them applied.
  const SwitchedRadarTerms terms = switched_terms(radar);

  std::vector<std::complex<float>> range_lines(n_pix);
  std::vector<std::complex<float>> z(n_pix);
  std::vector<double> intensity(n_pix, 0.0);
  for (int look = 0; look < looks; ++look) {
    const auto phase_stream = kCoherentPhaseStream + static_cast<std::uint32_t>(look);
    const auto noise_stream = kCoherentNoiseStream + static_cast<std::uint32_t>(look);
    // Range compression per geometry line, then azimuth compression along
    // each bin, then the point targets at their exact positions.
#pragma omp parallel for schedule(dynamic, 8)
    for (int line = 0; line < lines; ++line) {
      range_compress_line(h, line, g.samples, img.element_power_w.data() + g.index(line, 0),
                          g.slant_range_m.data() + g.index(line, 0), bins, seed, phase_stream,
                          range_lines.data() + img.index(line, 0));
    }
#pragma omp parallel for schedule(static)
    for (int k = 0; k < lines; ++k) {
      azimuth_compress_line(h, k, lines, bins, range_lines.data(), 0, sim.noise_power_w, seed,
                            noise_stream, z.data() + img.index(k, 0));
    }
    for (std::size_t t = 0; t < sim.point_returns.size(); ++t) {
      add_point_target(h, sim.point_returns[t], img.point_power_w[t], lines, bins, 0, lines,
                       z.data(), 0);
    }
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n_pix; ++i) intensity[i] += double(std::norm(z[i])) / looks;
  }

  std::vector<float> out(n_pix);
#pragma omp parallel for schedule(static)
  for (int k = 0; k < lines; ++k) {
    const std::size_t i = img.index(k, 0);
    finish_coherent_line(terms, img.range, intensity.data() + i, img.mask.data() + i,
                         img.area_m2.data() + i, bins, out.data() + i);
  }
  return out;
}

}  // namespace ris
