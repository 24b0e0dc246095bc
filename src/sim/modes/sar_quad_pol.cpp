#include "ris/sim/sar_quad_pol.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <span>
#include <vector>

#include <fmt/format.h>

#include "ris/image/greytone_terms.h"
#include "ris/sim/slar_channels.h"
#include "ris/util/counter_rng.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "sim/modes/sar_coherent_parts.h"

namespace ris {

namespace {

using cd = std::complex<double>;
using cf = std::complex<float>;

constexpr std::uint32_t kQuadPolStream = 0x51504C00u;    // "QPL\0": the elements' vectors
constexpr std::uint32_t kQuadNoiseStream = 0x514E4F00u;  // "QNO\0" + channel: thermal noise
constexpr double kInvSqrt2 = 0.70710678118654752440;

// The Sinclair matrix a point target carries (receive-transmit index: HH,
// HV, VH, VV, the SBR tracer's), |S_pq|^2 in m^2.
std::array<cd, 4> target_sinclair(const PointTarget& t) {
  if (t.sinclair) return *t.sinclair;
  const double a = std::sqrt(t.rcs_m2);  // a trihedral: the calibrator's matrix
  return {cd(a), cd(0.0), cd(0.0), cd(a)};
}

// Range compression of one geometry line into three rows (HH, HV, VV):
// each element's scattering vector k = L z, the sinc weights shared by the
// three channels.
struct QuadRows {
  cf* hh;
  cf* hv;
  cf* vv;
};

void range_compress_quad_line(const detail::CoherentResponse& h, const SlarGeometry& g, int line,
                              const std::array<const float*, 3>& power_w,
                              const CategoryShapes& shapes, int bins, std::uint64_t seed,
                              const QuadRows& out) {
  std::fill(out.hh, out.hh + bins, cf(0.0f, 0.0f));
  std::fill(out.hv, out.hv + bins, cf(0.0f, 0.0f));
  std::fill(out.vv, out.vv + bins, cf(0.0f, 0.0f));
  const std::size_t row = g.index(line, 0);
  const float* range = g.slant_range_m.data() + row;
  const std::uint16_t* category = g.category.data() + row;
  for (int j = 0; j < g.samples; ++j) {
    const float p_hh = power_w[0][j], p_hv = power_w[1][j], p_vv = power_w[2][j];
    if (!(p_hh > 0.0f || p_hv > 0.0f || p_vv > 0.0f)) continue;
    const double R = range[j];
    const auto [b0, b1] = h.bins_near(R, bins);
    if (b0 > b1) continue;
    const ElementFactor L = element_factor(p_hh, p_hv, p_vv, shapes[category[j]]);
    CounterRng rng(seed, static_cast<std::uint32_t>(j), static_cast<std::uint32_t>(line),
                   kQuadPolStream);
    // z: unit complex Gaussian (E |z_i|^2 = 1: parts N(0, 1/2)).
    const double n0 = rng.normal(), n1 = rng.normal(), n2 = rng.normal(), n3 = rng.normal(),
                 n4 = rng.normal(), n5 = rng.normal();
    const cd z1(n0 * kInvSqrt2, n1 * kInvSqrt2), z2(n2 * kInvSqrt2, n3 * kInvSqrt2),
        z3(n4 * kInvSqrt2, n5 * kInvSqrt2);
    const cd phase = h.amp_r * detail::unit_phasor(-h.k4pi_lambda * R);
    const cd a_hh = L.l11 * z1 * phase;
    const cd a_hv = L.l22 * kInvSqrt2 * z2 * phase;  // k_2 = sqrt2 S_HV
    const cd a_vv = (L.l31 * z1 + L.l33 * z3) * phase;
    for (int b = b0; b <= b1; ++b) {
      const double w = h.sinc((R - (h.near + (b + 0.5) * h.dr)) * h.kx_r);
      out.hh[b] += cf(a_hh * w);
      out.hv[b] += cf(a_hv * w);
      out.vv[b] += cf(a_vv * w);
    }
  }
}

// Thermal noise of one channel on image line k (keyed by (seed, bin, line)).
void add_noise_line(int k, int bins, const std::vector<double>& noise_power_w, std::uint64_t seed,
                    std::uint32_t stream, cf* z_row) {
  if (noise_power_w.empty()) return;
  for (int b = 0; b < bins; ++b) {
    CounterRng rng(seed, static_cast<std::uint32_t>(b), static_cast<std::uint32_t>(k), stream);
    const double sigma = std::sqrt(0.5 * noise_power_w[static_cast<std::size_t>(b)]);
    const double re = rng.normal(), im = rng.normal();
    z_row[b] += cf(cd(sigma * re, sigma * im));
  }
}

// A point target's response in one channel: amplitude (complex, sqrt W)
// at phase 0 plus the two-way phase, as add_point_target places it.
void add_target(const detail::CoherentResponse& h, const PointReturn& pr, cd amplitude, int lines,
                int bins, cf* z) {
  const double R = pr.slant_range_m;
  const cd a = amplitude * h.amp * detail::unit_phasor(-h.k4pi_lambda * R);
  const auto [b0, b1] = h.bins_near(R, bins);
  const auto [k0, k1] = h.lines_near(pr.along_m, lines);
  for (int k = k0; k <= k1; ++k) {
    const double ha = h.sinc((pr.along_m - (k + 0.5) * h.ds) * h.kx_a);
    cf* row = z + static_cast<std::size_t>(k) * static_cast<std::size_t>(bins);
    for (int b = b0; b <= b1; ++b) {
      const double hr = h.sinc((R - (h.near + (b + 0.5) * h.dr)) * h.kx_r);
      row[b] += cf(a * (ha * hr));
    }
  }
}

}  // namespace

ElementFactor element_factor(double p_hh_w, double p_hv_w, double p_vv_w,
                             const ElementPolarimetry& shape) {
  double c11 = p_hh_w, c22 = 2.0 * p_hv_w, c33 = p_vv_w;
  cd rho = shape.rho_hhvv;
  switch (shape.shape) {
    case CovarianceShape::coherent_surface:
      rho = 1.0;
      break;
    case CovarianceShape::dipole_volume: {
      // span (3/8) [1 0 1/3; 0 2/3 0; 1/3 0 1] (Freeman & Durden 1998, eq. 7).
      const double span = c11 + c22 + c33;
      c11 = c33 = 0.375 * span;
      c22 = 0.25 * span;
      rho = 1.0 / 3.0;
      break;
    }
    case CovarianceShape::correlated:
      break;
  }
  // Cholesky of [c11 0 c13; 0 c22 0; c13* 0 c33] with c13 = rho sqrt(c11 c33):
  // L31 = c31 / L11 = conj(rho) sqrt(c33), L33 = sqrt(c33 (1 - |rho|^2)).
  ElementFactor f;
  f.l11 = std::sqrt(std::max(c11, 0.0));
  f.l22 = std::sqrt(std::max(c22, 0.0));
  const double s33 = std::sqrt(std::max(c33, 0.0));
  f.l31 = c11 > 0.0 ? std::conj(rho) * s33 : cd(0.0);
  f.l33 = c11 > 0.0 ? s33 * std::sqrt(std::max(0.0, 1.0 - std::norm(rho))) : s33;
  return f;
}

CategoryShapes scene_polarimetry(const Scene& scene, const Sigma0Source& sigma0,
                                 const RadarParams& radar) {
  std::vector<std::uint8_t> used(65536, 0);
  for (std::size_t i = 0; i < scene.category.size(); ++i) {
    if (scene.valid[i]) used[scene.category[i]] = 1;
  }
  CategoryShapes out(65536);
  for (std::size_t c = 0; c < used.size(); ++c) {
    if (!used[c]) continue;
    const auto id = static_cast<std::uint16_t>(c);
    const CategoryPolarimetry p = category_polarimetry(sigma0, id, radar.frequency_hz);
    if (!(std::abs(p.rho_hhvv) <= 1.0)) {
      throw InputError(sigma0.description(), "rho_hhvv",
                       fmt::format("category '{}' ({}): |rho_hhvv| = {:g} exceeds 1; a "
                                   "correlation coefficient lies in the unit disc",
                                   sigma0.category_name(id), c, std::abs(p.rho_hhvv)));
    }
    out[c] = {p.shape, p.rho_hhvv};
  }
  return out;
}

RadarParams quad_pol_channel(const RadarParams& radar, Polarisation polarisation) {
  RadarParams r = radar;
  r.polarisation = polarisation;
  r.sar.quad_pol = false;
  r.channels.clear();
  return r;
}

std::vector<SlarSimulation> simulate_quad_pol_channels(const Scene& scene, const RadarParams& radar,
                                                       const Sigma0Source& sigma0,
                                                       const SlarOptions& options) {
  RIS_CHECK(radar.mode == RadarMode::sar && radar.sar.coherent && radar.sar.quad_pol);
  std::vector<SlarChannel> channels;
  for (Polarisation p : {Polarisation::HH, Polarisation::HV, Polarisation::VV}) {
    channels.push_back({quad_pol_channel(radar, p), &sigma0, ""});
  }
  SlarOptions o = options;
  o.polarimetric_channels = true;
  return simulate_slar_channels(scene, channels, o);
}

QuadPolImages form_quad_pol(const std::array<const SlarSimulation*, 3>& sims,
                            const CategoryShapes& shapes, const std::vector<PointTarget>& targets,
                            std::uint64_t seed) {
  RIS_CHECK(shapes.size() == 65536);
  const SlarSimulation& hh = *sims[0];
  const SlarGeometry& g = hh.geometry;
  const SlarImage& img = hh.image;
  for (const SlarSimulation* s : sims) {
    RIS_CHECK(s->image.element_power_w.size() == g.flags.size());
    RIS_CHECK(s->image.lines == img.lines && s->image.bins == img.bins);
  }
  RIS_CHECK(g.category.size() == g.flags.size() && img.lines == g.lines);
  const int lines = img.lines, bins = img.bins;
  const std::size_t n_pix = static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins);
  const detail::CoherentResponse h(detail::SincTable::shared(), img, hh.radar);
  const SwitchedRadarTerms terms = switched_terms(hh.radar);

  // Range compression of the three independent channels per geometry line.
  std::array<std::vector<cf>, 3> range_lines;
  for (auto& r : range_lines) r.resize(n_pix);
#pragma omp parallel for schedule(dynamic, 8)
  for (int line = 0; line < lines; ++line) {
    const std::size_t e = g.index(line, 0), o = img.index(line, 0);
    range_compress_quad_line(
        h, g, line,
        {sims[0]->image.element_power_w.data() + e, sims[1]->image.element_power_w.data() + e,
         sims[2]->image.element_power_w.data() + e},
        shapes, bins, seed,
        {range_lines[0].data() + o, range_lines[1].data() + o, range_lines[2].data() + o});
  }
  // Azimuth compression (no noise yet: HV and VH share it), then each
  // channel's own thermal noise.
  QuadPolImages q;
  q.lines = lines;
  q.bins = bins;
  for (auto& z : q.slc) z.resize(n_pix);
  static const std::vector<double> kNoNoise;
  constexpr std::array<std::size_t, 3> kInto = {0, 1, 3};  // HH, HV, VV (VH: HV's copy)
#pragma omp parallel for schedule(static)
  for (int k = 0; k < lines; ++k) {
    const std::size_t i = img.index(k, 0);
    for (std::size_t c = 0; c < 3; ++c) {
      detail::azimuth_compress_line(h, k, lines, bins, range_lines[c].data(), 0, kNoNoise, seed, 0,
                                    q.slc[kInto[c]].data() + i);
    }
    std::copy_n(q.slc[1].data() + i, bins, q.slc[2].data() + i);
  }
  for (auto& r : range_lines) std::vector<cf>().swap(r);
  // Point targets: S_pq scaled by the radar equation at their position
  // (the line engine's power for the target's rcs, over that rcs).
  for (std::size_t t = 0; t < hh.point_returns.size(); ++t) {
    const PointReturn& pr = hh.point_returns[t];
    const PointTarget& target = targets.at(pr.target);
    const double scale = std::sqrt(img.point_power_w[t] / target.rcs_m2);
    const std::array<cd, 4> s = target_sinclair(target);
    // The images are named transmit first (HV: transmit H, receive V, as
    // ris names polarisations); S is indexed receive-transmit.
    constexpr std::array<std::size_t, 4> kS = {0, 2, 1, 3};
    for (std::size_t c = 0; c < 4; ++c) {
      add_target(h, pr, scale * s[kS[c]], lines, bins, q.slc[c].data());
    }
  }
#pragma omp parallel for schedule(static)
  for (int k = 0; k < lines; ++k) {
    const std::size_t i = img.index(k, 0);
    for (std::size_t c = 0; c < 4; ++c) {
      add_noise_line(k, bins, hh.noise_power_w, seed,
                     kQuadNoiseStream + static_cast<std::uint32_t>(c), q.slc[c].data() + i);
    }
  }
  // The switches as the mean image has them (on the amplitude: the square
  // root of the intensity's factor); NaN for no data.
  for (auto& v : q.intensity) v.resize(n_pix);
  const float nan = std::numeric_limits<float>::quiet_NaN();
#pragma omp parallel for schedule(static)
  for (int k = 0; k < lines; ++k) {
    for (int b = 0; b < bins; ++b) {
      const std::size_t i = img.index(k, b);
      const bool nodata = img.mask[i] & pixel_flag::kNoData;
      const double f = nodata ? 0.0
                              : range_correction(terms, img.range.centre_m(b)) *
                                    area_correction(terms, img.area_m2[i]);
      const double a = std::sqrt(f);
      for (std::size_t c = 0; c < 4; ++c) {
        cf& z = q.slc[c][i];
        if (nodata) {
          z = cf(nan, nan);
          q.intensity[c][i] = nan;
          continue;
        }
        z = cf(cd(z) * a);
        q.intensity[c][i] = std::norm(z);
      }
    }
  }
  return q;
}

}  // namespace ris
