// Polarimetric decompositions of one averaged pixel, and the Pauli picture
// (docs/polarimetry.md has the equations, sources and conventions).
//
// Cloude-Pottier (Cloude & Pottier, IEEE TGRS 35(1), 1997): the eigenvalues
// l1 >= l2 >= l3 of T3 (negative ones, rounding, taken as 0) and their unit
// eigenvectors e_i; p_i = l_i / (l1 + l2 + l3);
//   entropy     H = -sum p_i log3 p_i                    in [0, 1]
//   anisotropy  A = (l2 - l3) / (l2 + l3)                 in [0, 1] (0 when l2 + l3 <= 1e-12 span)
//   mean alpha  alpha = sum p_i acos |e_i[0]|              in [0, pi/2] rad
// (e_i[0]: the eigenvector's HH+VV Pauli component).
//
// Freeman-Durden three-component (Freeman & Durden, IEEE TGRS 36(3), 1998)
// on C3, with PolSARpro's conventions (freeman_decomposition.c of PolSARpro
// v5, E. Pottier and J. Strzelczyk, IETR; ris's own code): the volume of
// randomly oriented dipoles fv = 3 C22 / 2 is removed (C11 -= fv, C33 -= fv,
// C13 -= fv / 3); when what is left of C11 or C33 is <= 0 the pixel is all
// volume (fv = 3 span / 8, fs = fd = 0); otherwise |C13|^2 is limited to
// C11 C33 (keeping its phase), and the sign of Re C13 chooses the branch:
//   Re C13 >= 0  surface dominant, alpha = -1 fixed:
//                fd = (C11 C33 - |C13|^2) / (C11 + C33 + 2 Re C13), fs = C33 - fd,
//                beta = |C13 + fd| / fs
//   Re C13 <  0  double bounce dominant, beta = 1 fixed:
//                fs = (C11 C33 - |C13|^2) / (C11 + C33 - 2 Re C13), fd = C33 - fs,
//                alpha = |fs - C13| / fd
// Powers Ps = fs (1 + beta^2), Pd = fd (1 + alpha^2), Pv = 8 fv / 3.
// freeman_durden gives them as computed (a power may be negative);
// freeman_durden_image then clips every power, as PolSARpro does, to
// [span_min, span_max] of the image's averaged spans (span_min at least
// 1e-30).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "ris/backscatter/polarimetric_matrix.h"
#include "ris/image/polsar/quad_pol_slc.h"

namespace ris {

struct CloudePottier {
  double entropy = 0.0;
  double anisotropy = 0.0;
  double alpha_rad = 0.0;
  std::array<double, 3> eigenvalues{};  // descending, negatives kept as computed
};
CloudePottier cloude_pottier(const Hermitian3& t3);

struct FreemanDurden {
  double surface = 0.0;        // Ps (PolSARpro's Freeman_Odd)
  double double_bounce = 0.0;  // Pd (Freeman_Dbl)
  double volume = 0.0;         // Pv (Freeman_Vol)
};
FreemanDurden freeman_durden(const Hermitian3& c3);

// Every pixel of an averaged image: H, A, alpha from its T3 (c may be C3 or
// T3), Freeman-Durden from its C3 with the span clipping of the header.
std::vector<CloudePottier> cloude_pottier_image(const CovarianceImage& c);
std::vector<FreemanDurden> freeman_durden_image(const CovarianceImage& c);

// The Pauli picture, PolSARpro's colours: red |HH - VV| / sqrt2 = sqrt T22,
// green sqrt2 |HV| = sqrt T33, blue |HH + VV| / sqrt2 = sqrt T11, each in dB
// and stretched on its own between its 2nd and 98th percentile over the
// image to 0..255 (a non-finite pixel is black). Interleaved RGB, rows x cols.
std::vector<std::uint8_t> pauli_rgb(const CovarianceImage& c);

}  // namespace ris
