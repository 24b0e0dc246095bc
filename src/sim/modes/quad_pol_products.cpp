#include "ris/sim/quad_pol_products.h"

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <complex>
#include <limits>
#include <string>

#include "ris/image/polsar/polsar_products.h"
#include "ris/image/polsar/quad_pol_slc.h"
#include "ris/image/slant_georef.h"
#include "ris/io/raster_io.h"
#include "ris/sensor/polarisation.h"

namespace ris {

namespace {

std::string lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

}  // namespace

nlohmann::json write_quad_pol_products(const std::filesystem::path& dir, const Scene& scene,
                                       const SlarSimulation& hh, const QuadPolImages& q) {
  const SlarImage& img = hh.image;
  const Georef gcps = slant_georef(scene, hh.track, img);
  nlohmann::json products = nlohmann::json::object();
  QuadPolSlc set;
  set.cols = q.bins;
  set.rows = q.lines;
  set.format = "simulated";
  std::array<std::vector<std::complex<float>>*, 4> into = {&set.hh, &set.hv, &set.vh, &set.vv};
  for (std::size_t c = 0; c < 4; ++c) {
    const std::string pol(to_string(kQuadPolOrder[c]));
    const std::string file = "slc_" + lower(pol) + ".tif";
    const RasterMetadata meta{
        {"RIS_PRODUCT", "single-look complex image " + pol + " (transmit " + pol.substr(0, 1) +
                            ", receive " + pol.substr(1, 1) + ")"},
        {"RIS_UNITS", "sqrt(W): |z|^2 is the pixel's power (W)"},
        {"RIS_ROWS", "azimuth lines, track start first"},
        {"RIS_COLUMNS", "slant-range bins, near range first"},
        {"RIS_NEAR_SLANT_RANGE_M", fmt::format("{:.6f}", img.range.near_m)},
        {"RIS_RANGE_BIN_M", fmt::format("{:.6f}", img.range.bin_m)},
        {"RIS_LINE_SPACING_M", fmt::format("{:.6f}", img.line_spacing_m)},
        {"RIS_POLARISATION", pol},
        {"RIS_VERSION", RIS_VERSION}};
    write_geotiff(dir / file, q.slc[c].data(), q.bins, q.lines, &gcps,
                  std::numeric_limits<double>::quiet_NaN(), meta, "slc_" + lower(pol));
    products[file] = "complex64 single-look complex image " + pol + " (sqrt W), slant range";
    set.sources[c] = file;
    *into[c] = q.slc[c];
  }
  // The decompositions of the simulated set, as ris polsar makes them of a
  // real one (so like is compared with like).
  const nlohmann::json polsar =
      write_polsar_products(set, {kQuadPolWindow, kQuadPolWindow}, dir / "polsar", true);
  products["polsar/"] = fmt::format(
      "ris polsar --syntheses of the four SLCs at a {0} x {0} boxcar: c3.tif, t3.tif, "
      "h_a_alpha.tif, freeman_durden.tif, pauli.png, the dual- and compact-pol images "
      "(dual_h_c2.tif, dual_v_c2.tif, compact_rh.tif, compact_rv.tif, compact_c2.tif, "
      "m_chi.tif), metadata.json",
      kQuadPolWindow);
  nlohmann::json info = {
      {"channels", {"HH", "HV", "VH", "VV"}},
      {"naming", "transmit first (HV: transmit H, receive V)"},
      {"slc_units", "sqrt(W): |z|^2 is the pixel's power in watts, as speckled_power_slant"},
      {"reciprocity", "HV and VH are one reciprocal image plus each its own thermal noise"},
      {"looks", 1},
      {"polsar_window", {kQuadPolWindow, kQuadPolWindow}},
      {"polsar", polsar},
      {"covariance",
       "per element: C11 = P_HH, C22 = 2 P_HV, C33 = P_VV, C13 = rho sqrt(C11 C33) by the "
       "category's model family (docs/polarimetry.md); point targets carry their Sinclair "
       "matrix (a user's target: a trihedral's)"}};
  return {{"products", products}, {"quad_pol", info}};
}

}  // namespace ris
