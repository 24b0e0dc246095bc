// Impulse-response measurements of the point targets of a SLAR/SAR run
// (ris/image/impulse_response.h applied at each seen target), as written to
// metadata.json by `ris simulate --targets` (docs/modes.md).
//
// Which image is measured: the coherent SAR's intensity (speckle and the
// sinc sidelobes are in it; sinc interpolation of the cuts), otherwise the
// mean power before fading (the designed box response without the fading's
// random fluctuation; linear interpolation).
//
// Example:
//   auto irfs = ris::measure_point_targets(sim, pictures, coherent);
//   metadata["point_targets"] = ris::point_target_irf_json(irfs, sim, "targets.toml", coherent);
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/image/impulse_response.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

struct PointTargetIrf {
  PointReturn target;
  IrfMeasurement irf;
};

// One entry per seen target whose range falls in the swath.
std::vector<PointTargetIrf> measure_point_targets(const SlarSimulation& sim,
                                                  const SlarPictures& pictures, bool coherent);

nlohmann::json point_target_irf_json(const std::vector<PointTargetIrf>& irfs,
                                     const SlarSimulation& sim, const std::string& targets_file,
                                     bool coherent);

}  // namespace ris
