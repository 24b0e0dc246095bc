// A quad-pol SAR run's own products (ris/sim/sar_quad_pol.h), beside each
// channel's single-pol products (ris/sim/slar_channel_products.h, suffixes
// _hh, _hv, _vh, _vv): written into the run's staging folder.
//
//   slc_hh.tif, slc_hv.tif, slc_vh.tif, slc_vv.tif
//       CFloat32 single-look complex images, slant range (rows azimuth
//       lines, columns range bins, as speckled_power_slant.tif), |z|^2 in W,
//       no data NaN, the slant products' GCPs: what ris polsar --hh ... reads
//   polsar/   ris polsar's products of those four at a 7 x 7 boxcar
//       (ris/image/polsar/polsar_products.h): c3.tif, t3.tif,
//       h_a_alpha.tif, freeman_durden.tif, pauli.png, metadata.json
//
// Example:
//   nlohmann::json j = ris::write_quad_pol_products(staging, scene, sims[0], q);
#pragma once

#include <filesystem>

#include <nlohmann/json.hpp>

#include "ris/scene/scene.h"
#include "ris/sim/sar_quad_pol.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

// The boxcar of the simulated run's polsar/ products (PolSARpro's and
// ris polsar's default window).
inline constexpr int kQuadPolWindow = 7;

// Writes the files above into dir (a staging folder); returns
// {"products": {file: description}, "quad_pol": {...}} for metadata.json.
// hh: the HH channel's simulation (its image grid and track).
nlohmann::json write_quad_pol_products(const std::filesystem::path& dir, const Scene& scene,
                                       const SlarSimulation& hh, const QuadPolImages& q);

}  // namespace ris
