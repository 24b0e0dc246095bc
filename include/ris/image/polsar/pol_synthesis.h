// Dual- and compact-pol images synthesised from a quad-pol SLC set (issue 33;
// docs/polarimetry.md, "Dual- and compact-pol syntheses"): what a radar that
// transmits one polarisation and receives two would have measured of the
// same scene.
//
// Names are transmit first, as ris's channels (HV: transmit H, receive V).
//   dual_h        transmit H, receive H and V: (HH, HV)
//   dual_v        transmit V, receive V and H: (VV, VH)
//   compact_ctlr  transmit right-circular, receive H and V (Raney's hybrid
//                 polarity, RISAT-1 and the RADARSAT Constellation; Raney,
//                 IEEE TGRS 45(11), 2007): the transmitted field
//                 (1, -i)/sqrt2 in (H, V), so
//                   E_RH = (S_HH - i S_VH) / sqrt2   (receive H: from H, from V)
//                   E_RV = (S_HV - i S_VV) / sqrt2
// The two-channel covariance C2 = <[a, b]^T [a, b]^H> is averaged over a
// boxcar as ris polsar averages C3. From the compact C2, the Stokes vector
// (Raney 2007, eq. 5)
//   g0 = <|E_RH|^2 + |E_RV|^2>, g1 = <|E_RH|^2 - |E_RV|^2>,
//   g2 = 2 Re <E_RH E_RV*>,     g3 = -2 Im <E_RH E_RV*>,
// the degree of polarisation m = sqrt(g1^2 + g2^2 + g3^2) / g0, and the
// m-chi decomposition (Raney, Cahill, Patterson & Bruno, IEEE GRSL 9(5),
// 2012) with sin 2chi = -g3 / (m g0):
//   odd = m g0 (1 + sin 2chi) / 2, even = m g0 (1 - sin 2chi) / 2,
//   volume = g0 (1 - m).
// With this sign a trihedral (S = I) is all odd bounce and a dihedral all
// even bounce (the tests fix it); a dihedral rolled 45 deg about the line
// of sight is even bounce too (compact pol cannot tell it from a volume by
// its cross-pol power, only by m).
//
// Example:
//   ris::TwoChannelSlc c = ris::synthesise_two_channel(set, ris::TwoChannelMode::compact_ctlr);
//   ris::CovarianceImage c2 = ris::boxcar_c2(c, 7, 7);
//   ris::StokesMChi p = ris::stokes_m_chi(c2.m[i]);
#pragma once

#include <complex>
#include <string>
#include <vector>

#include "ris/image/polsar/quad_pol_slc.h"

namespace ris {

enum class TwoChannelMode { dual_h, dual_v, compact_ctlr };

struct TwoChannelSlc {
  int cols = 0, rows = 0;
  std::vector<std::complex<float>> a, b;  // rows x cols each
  std::string a_name, b_name;             // "HH", "HV"; "VV", "VH"; "RH", "RV"
};

TwoChannelSlc synthesise_two_channel(const QuadPolSlc& s, TwoChannelMode mode);

// C2 per pixel in the top-left 2 x 2 of a CovarianceImage (the rest zero),
// boxcar-averaged as boxcar_average (both window sides odd).
CovarianceImage boxcar_c2(const TwoChannelSlc& s, int window_rows, int window_cols);

struct StokesMChi {
  double g0 = 0.0, g1 = 0.0, g2 = 0.0, g3 = 0.0;
  double m = 0.0;        // degree of polarisation, 0..1
  double chi_rad = 0.0;  // ellipticity angle, asin(-g3 / (m g0)) / 2
  double odd = 0.0, even = 0.0, volume = 0.0;
};

// From a compact (CTLR) C2 (top-left 2 x 2 of c2); all zero for g0 <= 0 or
// a non-finite pixel's NaN throughout.
StokesMChi stokes_m_chi(const Hermitian3& c2);

}  // namespace ris
