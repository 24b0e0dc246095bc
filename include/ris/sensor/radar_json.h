// RadarParams and RadarDerived as JSON, for a run's metadata.json: every
// input in SI units (keys carry the unit: "_m", "_s", "_hz", "_rad", "_w"),
// every derived quantity, and the switches of equation 15.
//
// Example:
//   nlohmann::json meta;
//   meta["radar"] = ris::radar_to_json(radar);
//   meta["radar_derived"] = ris::derived_to_json(ris::derive(radar));
#pragma once

#include <nlohmann/json.hpp>

#include "ris/sensor/radar_derived.h"
#include "ris/sensor/radar_params.h"

namespace ris {

nlohmann::json radar_to_json(const RadarParams& radar);
nlohmann::json derived_to_json(const RadarDerived& derived);

}  // namespace ris
