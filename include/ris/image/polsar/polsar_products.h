// The products of `ris polsar` (docs/polarimetry.md, "Products"): from a
// quad-pol SLC set, averaged over a boxcar window,
//   c3.tif              9 float bands C11, C12_real, C12_imag, C13_real,
//                       C13_imag, C22, C23_real, C23_imag, C33 (PolSARpro's
//                       element names; C22 = 2 <|HV|^2>)
//   t3.tif              the same for T11 ... T33
//   h_a_alpha.tif       entropy, anisotropy, alpha_deg
//   freeman_durden.tif  Freeman_Odd (surface), Freeman_Dbl, Freeman_Vol
//   pauli.png           the Pauli picture (red |HH-VV|, green |HV|, blue |HH+VV|)
//   metadata.json       inputs, window, conventions, summary statistics
// and with `syntheses` the dual- and compact-pol images of the same set
// (ris/image/polsar/pol_synthesis.h), at the same window:
//   dual_h_c2.tif, dual_v_c2.tif, compact_c2.tif
//                       4 float bands C11, C12_real, C12_imag, C22 of
//                       (HH, HV), (VV, VH), (RH, RV)
//   compact_rh.tif, compact_rv.tif
//                       the compact (CTLR) SLCs, CFloat32
//   m_chi.tif           g0, g1, g2, g3, m, chi_deg, odd, even, volume
// written into a staged folder that appears whole or not at all.
//
// Example:
//   ris::QuadPolSlc s = ris::read_quad_pol_nisar("product.h5");
//   nlohmann::json summary = ris::write_polsar_products(s, {7, 7}, "out/polsar");
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "ris/image/polsar/quad_pol_slc.h"

namespace ris {

struct PolsarWindow {
  int rows = 7, cols = 7;  // odd; 1 x 1: single look
};

nlohmann::json write_polsar_products(const QuadPolSlc& s, const PolsarWindow& window,
                                     const std::filesystem::path& out_dir, bool syntheses = false);

}  // namespace ris
