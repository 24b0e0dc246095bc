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

#include <optional>
#include <span>
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

// The pixels a target's measurement reads (its peak search and cuts),
// clipped to the image: lines [line0, line0 + lines) x bins [bin0, bin0 +
// bins). None when its range falls outside the swath (it is not measured).
// A streamed run keeps these windows as the lines go by
// (src/sim/stream/slar_stream_targets.h).
struct IrfWindow {
  int line0 = 0, lines = 0, bin0 = 0, bins = 0;
};
std::optional<IrfWindow> point_target_irf_window(const SlarImage& img, const PointReturn& target);

// The measurement of measure_point_targets from the window's pixels alone
// (window_power: w.lines x w.bins, the image measured): the same numbers.
PointTargetIrf measure_point_target_in_window(const SlarImage& img, const PointReturn& target,
                                              const IrfWindow& w,
                                              std::span<const float> window_power, bool coherent);

nlohmann::json point_target_irf_json(const std::vector<PointTargetIrf>& irfs,
                                     const SlarSimulation& sim, const std::string& targets_file,
                                     bool coherent);

}  // namespace ris
