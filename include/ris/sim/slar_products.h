// The products of a SLAR simulation, written into one output folder through
// StagedDirectory: every file appears together when all are complete, or none
// does (docs/outputs.md describes each product).
//
//   slant_range.png          greytones, slant range (rows: azimuth lines,
//                            track start first; columns: range bins, near first)
//   ground_range.png         greytones, ground range over h_ref
//   mean_power_slant.tif     float32, mean received power (W) before speckle
//   speckled_power_slant.tif float32, power after fading (W)
//   mask_slant.tif           uint8: 1 shadow, 2 layover, 4 no data
//   scene_mask.tif           uint8 on the scene grid: 1 shadow, 2 layover,
//                            4 no data, 8 back-facing, 16 outside swath
//   local_incidence_deg.tif  float32 on the scene grid, degrees
//   shadowmap.txt            the seed's shadow map
//   metadata.json            inputs, derived quantities, software version
//
// Example:
//   ris::write_slar_products("out", scene, sim, pictures, info);
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include <nlohmann/json.hpp>

#include "ris/scene/scene.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

// Where the inputs came from, for metadata.json.
struct SlarRunInfo {
  std::string scene_path;
  std::string radar_path;
  std::string backscatter_path;
  std::uint64_t seed = 0;
  int threads = 0;
};

// metadata.json's content.
nlohmann::json slar_metadata(const Scene& scene, const SlarSimulation& sim,
                             const SlarPictures& pictures, const SlarRunInfo& info);

void write_slar_products(const std::filesystem::path& out_dir, const Scene& scene,
                         const SlarSimulation& sim, const SlarPictures& pictures,
                         const SlarRunInfo& info);

}  // namespace ris
