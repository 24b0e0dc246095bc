// The page's optical and thermal views of the current scene (docs/serve.md,
// "Other sensors"; issue 35): the scene grid rendered by `ris sensor`'s code
// (ris/sensors_eo/) with the shipped sensor file data/sensors_eo/<kind>.toml
// (its date and place; the time of day from the request), the surface table
// named after the session's backscatter library (as `ris sensor` without
// --table), as the PNG preview `ris sensor` writes. North-up on the scene's
// grid: one pixel per cell, so it lies over the scene view.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ris/scene/scene.h"

namespace ris {

// kind: "optical" or "thermal"; minute_of_day: 0..1439 (UTC) replacing the
// file's time, or nullopt for the file's. Throws InputError (source
// "request") naming `kind` or `minute`, and the table's error for a scene
// category the table lacks (with the table's name).
std::vector<std::uint8_t> sensor_view_png(const Scene& scene, const std::string& library,
                                          const std::string& kind,
                                          std::optional<int> minute_of_day);

}  // namespace ris
