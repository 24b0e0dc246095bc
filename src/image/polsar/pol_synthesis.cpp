// Dual- and compact-pol syntheses (ris/image/polsar/pol_synthesis.h).
#include "ris/image/polsar/pol_synthesis.h"

#include <algorithm>
#include <cmath>

#include "ris/util/error.h"

namespace ris {

TwoChannelSlc synthesise_two_channel(const QuadPolSlc& s, TwoChannelMode mode) {
  const std::size_t n = static_cast<std::size_t>(s.cols) * static_cast<std::size_t>(s.rows);
  RIS_CHECK(s.hh.size() == n && s.hv.size() == n && s.vh.size() == n && s.vv.size() == n);
  TwoChannelSlc out;
  out.cols = s.cols;
  out.rows = s.rows;
  switch (mode) {
    case TwoChannelMode::dual_h:
      out.a = s.hh;
      out.b = s.hv;
      out.a_name = "HH";
      out.b_name = "HV";
      break;
    case TwoChannelMode::dual_v:
      out.a = s.vv;
      out.b = s.vh;
      out.a_name = "VV";
      out.b_name = "VH";
      break;
    case TwoChannelMode::compact_ctlr: {
      // Transmit (1, -i)/sqrt2: receive H sums HH and VH (transmit V,
      // receive H) with -i on the V-transmitted part; receive V likewise.
      out.a.resize(n);
      out.b.resize(n);
      const std::complex<float> minus_i(0.0f, -1.0f);
      const float inv_sqrt2 = 0.70710678118654752f;
#pragma omp parallel for schedule(static)
      for (std::size_t i = 0; i < n; ++i) {
        out.a[i] = (s.hh[i] + minus_i * s.vh[i]) * inv_sqrt2;
        out.b[i] = (s.hv[i] + minus_i * s.vv[i]) * inv_sqrt2;
      }
      out.a_name = "RH";
      out.b_name = "RV";
      break;
    }
  }
  return out;
}

CovarianceImage boxcar_c2(const TwoChannelSlc& s, int window_rows, int window_cols) {
  CovarianceImage c;
  c.cols = s.cols;
  c.rows = s.rows;
  c.m.resize(s.a.size());
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < s.a.size(); ++i) {
    const Complex a(s.a[i]), b(s.b[i]);
    Hermitian3& m = c.m[i];
    m(0, 0) = std::norm(a);
    m(0, 1) = a * std::conj(b);
    m(1, 0) = std::conj(m(0, 1));
    m(1, 1) = std::norm(b);
  }
  return boxcar_average(c, window_rows, window_cols);
}

StokesMChi stokes_m_chi(const Hermitian3& c2) {
  StokesMChi p;
  const double h = c2(0, 0).real(), v = c2(1, 1).real();
  const Complex hv = c2(0, 1);
  p.g0 = h + v;
  p.g1 = h - v;
  p.g2 = 2.0 * hv.real();
  p.g3 = -2.0 * hv.imag();
  if (!std::isfinite(p.g0)) {
    p.m = p.chi_rad = p.odd = p.even = p.volume = p.g0;
    return p;
  }
  if (p.g0 <= 0.0) return p;
  const double pol = std::sqrt(p.g1 * p.g1 + p.g2 * p.g2 + p.g3 * p.g3);
  p.m = std::min(1.0, pol / p.g0);  // a boxcar mean is a valid Stokes vector: <= 1 up to rounding
  const double s2chi = pol > 0.0 ? std::clamp(-p.g3 / pol, -1.0, 1.0) : 0.0;
  p.chi_rad = 0.5 * std::asin(s2chi);
  p.odd = p.m * p.g0 * (1.0 + s2chi) / 2.0;
  p.even = p.m * p.g0 * (1.0 - s2chi) / 2.0;
  p.volume = p.g0 * (1.0 - p.m);
  return p;
}

}  // namespace ris
