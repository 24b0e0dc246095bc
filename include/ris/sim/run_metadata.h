// The parts of metadata.json every simulation mode writes the same way
// (SLAR/SAR: ris/sim/slar_products.h; PPI: ris/sim/ppi_products.h): the
// software and the "inputs" block (scene grid and CRS, elevation range,
// categories, radar as parsed, backscatter, seed, threads).
//
// Example:
//   nlohmann::json j = ris::run_header_json("ppi");
//   j["inputs"] = ris::run_inputs_json({scene, h_min, h_max, nodata}, radar, sim.categories,
//                                      sim.category_names, sim.backscatter_description, info);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/run_info.h"

namespace ris {

// A scene's grid and what metadata says of its cells. The arrays of `grid`
// are not read (a streamed run has none in memory).
struct SceneSummary {
  const Scene& grid;
  float elevation_min_m = 0.0f;  // of the cells with data (+inf when none)
  float elevation_max_m = 0.0f;  // (-inf when none)
  std::int64_t nodata_cells = 0;
};

// The summary of an in-memory scene.
SceneSummary summarise_scene(const Scene& scene);

// {"software": ..., "mode": mode, "earth_model": "flat"}.
nlohmann::json run_header_json(const std::string& mode);

nlohmann::json run_inputs_json(const SceneSummary& scene, const RadarParams& radar,
                               const std::vector<std::uint16_t>& categories,
                               const std::vector<std::string>& category_names,
                               const std::string& backscatter_description, const SlarRunInfo& info);

// metadata.json's "products" (file -> description) with only the files of
// the selected products (and metadata.json itself).
nlohmann::json selected_products(const nlohmann::json& products, const ProductSelection& selection);

}  // namespace ris
