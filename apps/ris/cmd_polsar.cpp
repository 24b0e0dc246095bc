// ris polsar: covariance, coherency, Cloude-Pottier H/A/alpha, Freeman-Durden
// and the Pauli picture of a quad-pol SLC set, simulated or real
// (docs/polarimetry.md).
//
//   ris polsar --hh hh.tif --hv hv.tif --vh vh.tif --vv vv.tif --out polsar/
//   ris polsar --product RSLC.h5 [--frequency A] --window 5 --out polsar/
//   ris polsar ... --window 7x5      # 7 rows (azimuth) x 5 columns (range)
//
// Writes c3.tif, t3.tif, h_a_alpha.tif, freeman_durden.tif, pauli.png and
// metadata.json into --out, all or nothing (ris/image/polsar/polsar_products.h).
#include <fmt/format.h>

#include <array>
#include <memory>
#include <string>

#include "command_registry.h"
#include "ris/image/polsar/polsar_products.h"
#include "ris/util/error.h"

namespace ris::app {
namespace {

struct PolsarOptions {
  std::string hh, hv, vh, vv, product, frequency = "A", window = "7", out;
  bool syntheses = false;
};

// "N" (N x N) or "RxC", each odd and in 1..101.
PolsarWindow parse_window(const std::string& text) {
  PolsarWindow w;
  const auto x = text.find('x');
  try {
    std::size_t used = 0;
    const std::string r = x == std::string::npos ? text : text.substr(0, x);
    const std::string c = x == std::string::npos ? text : text.substr(x + 1);
    w.rows = std::stoi(r, &used);
    if (used != r.size()) throw std::invalid_argument(r);
    w.cols = std::stoi(c, &used);
    if (used != c.size()) throw std::invalid_argument(c);
  } catch (const std::exception&) {
    throw InputError(
        "", "--window",
        fmt::format("expected N or RxC (odd pixel counts, e.g. 7 or 7x5), got '{}'", text));
  }
  for (int v : {w.rows, w.cols}) {
    if (v < 1 || v > 101 || v % 2 == 0) {
      throw InputError(
          "", "--window",
          fmt::format("window sides must be odd and in 1..101 pixels, got '{}'", text));
    }
  }
  return w;
}

void run_polsar(const PolsarOptions& o) {
  const bool rasters = !o.hh.empty() || !o.hv.empty() || !o.vh.empty() || !o.vv.empty();
  if (rasters == !o.product.empty()) {
    throw InputError("", "--product",
                     "give either --product (a NISAR/UAVSAR RSLC HDF5 file) or the four rasters "
                     "--hh --hv --vh --vv");
  }
  if (rasters && (o.hh.empty() || o.hv.empty() || o.vh.empty() || o.vv.empty())) {
    throw InputError("", "--hh/--hv/--vh/--vv",
                     "a quad-pol set needs all four rasters (HV and VH both: reciprocity is "
                     "applied by averaging them)");
  }
  if (o.out.empty()) throw InputError("", "--out", "give the output folder");
  const PolsarWindow w = parse_window(o.window);
  const QuadPolSlc s = rasters ? read_quad_pol_rasters({o.hh, o.hv, o.vh, o.vv})
                               : read_quad_pol_nisar(o.product, o.frequency);
  const nlohmann::json j = write_polsar_products(s, w, o.out, o.syntheses);
  fmt::print("ris polsar: {} x {} pixels, window {} x {}, written to {}\n", s.cols, s.rows, w.rows,
             w.cols, o.out);
  const auto& st = j["statistics"];
  for (const char* key : {"entropy", "anisotropy", "alpha_deg"}) {
    if (st[key].is_null()) continue;
    fmt::print("  {:<11} mean {:8.4f}  min {:8.4f}  max {:8.4f}\n", key,
               st[key]["mean"].get<double>(), st[key]["min"].get<double>(),
               st[key]["max"].get<double>());
  }
}

void add_polsar(CLI::App& app) {
  auto o = std::make_shared<PolsarOptions>();
  auto* cmd = app.add_subcommand(
      "polsar",
      "Polarimetric products of a quad-pol SLC set: C3, T3, H/A/alpha, Freeman-Durden, Pauli");
  cmd->add_option("--hh", o->hh, "HH SLC raster (one complex band)");
  cmd->add_option("--hv", o->hv, "HV SLC raster");
  cmd->add_option("--vh", o->vh, "VH SLC raster");
  cmd->add_option("--vv", o->vv, "VV SLC raster");
  cmd->add_option("--product", o->product, "NISAR/UAVSAR RSLC HDF5 with HH, HV, VH and VV");
  cmd->add_option("--frequency", o->frequency, "The product's frequency: A or B")
      ->capture_default_str();
  cmd->add_option("--window", o->window, "Boxcar window: N or RxC odd pixels (rows x columns)")
      ->capture_default_str();
  cmd->add_option("--out", o->out, "Output folder")->required();
  cmd->add_flag("--syntheses", o->syntheses,
                "Also the dual-pol (HH+HV, VV+VH) and compact-pol (CTLR) images of the set: C2, "
                "the compact SLCs, Stokes and m-chi");
  cmd->callback([o] { run_polsar(*o); });
}

const Registration reg{"polsar", add_polsar};

}  // namespace
}  // namespace ris::app
