#include "ris/sim/run_metadata.h"

#include <algorithm>
#include <filesystem>
#include <limits>

#include "ris/sensor/radar_json.h"

namespace ris {

using nlohmann::json;

SceneSummary summarise_scene(const Scene& scene) {
  SceneSummary s{scene, std::numeric_limits<float>::infinity(),
                 -std::numeric_limits<float>::infinity(), 0};
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (!scene.valid[i]) {
      ++s.nodata_cells;
      continue;
    }
    s.elevation_min_m = std::min(s.elevation_min_m, scene.elevation_m[i]);
    s.elevation_max_m = std::max(s.elevation_max_m, scene.elevation_m[i]);
  }
  return s;
}

json run_header_json(const std::string& mode) {
  return {{"software", {{"name", "ris"}, {"version", RIS_VERSION}}},
          {"mode", mode},
          {"earth_model", "flat"}};
}

json run_inputs_json(const SceneSummary& s, const RadarParams& radar,
                     const std::vector<std::uint16_t>& categories,
                     const std::vector<std::string>& category_names,
                     const std::string& backscatter_description, const SlarRunInfo& info) {
  json cats = json::array();
  for (std::size_t i = 0; i < categories.size(); ++i)
    cats.push_back({{"id", categories[i]}, {"name", category_names[i]}});
  const Scene& g = s.grid;
  return {
      {"scene",
       {{"path", info.scene_path},
        {"rows", g.rows},
        {"cols", g.cols},
        {"cell_x_m", g.dx_m},
        {"cell_y_m", g.dy_m},
        {"origin_x_m", g.origin_x_m},
        {"origin_y_m", g.origin_y_m},
        {"crs_wkt", g.crs_wkt},
        {"elevation_min_m", s.elevation_min_m},
        {"elevation_max_m", s.elevation_max_m},
        {"nodata_cells", s.nodata_cells},
        {"categories", cats}}},
      {"radar", radar_to_json(radar)},
      {"backscatter", {{"path", info.backscatter_path}, {"description", backscatter_description}}},
      {"seed", info.seed},
      {"threads", info.threads}};
}

nlohmann::json selected_products(const nlohmann::json& products,
                                 const ProductSelection& selection) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [file, description] : products.items()) {
    const std::string stem = std::filesystem::path(file).stem().string();
    if (file == "metadata.json" || selection.wants(stem)) out[file] = description;
  }
  return out;
}

}  // namespace ris
