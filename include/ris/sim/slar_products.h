// The products of a SLAR simulation, written into one output folder through
// StagedDirectory: every file appears together when all are complete, or none
// does (docs/outputs.md describes each product).
//
//   slant_range.png          greytones, slant range (rows: azimuth lines,
//                            track start first; columns: range bins, near first);
//                            .tif above kMaxPngPixels (picture_file)
//   ground_range.png         greytones, ground range over h_ref (.tif likewise)
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
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include <optional>

#include <nlohmann/json.hpp>

#include "ris/image/radiometric_calibration.h"
#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"
#include "ris/sim/run_info.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

// The file name of a picture `stem` of cols x rows pixels: .png up to
// max_png_pixels, .tif above (kMaxPngPixels, ris/sim/run_info.h).
std::string picture_file(const std::string& stem, int cols, int rows,
                         std::int64_t max_png_pixels = kMaxPngPixels);

// metadata.json's "derived" "image" block (the slant-range image's layout,
// azimuth footprint and switches) and "greytone" block, shared with the
// acquisition run's (ris/sim/acquisition_products.h).
nlohmann::json slar_image_json(const SlarSimulation& sim);
nlohmann::json greytone_json(const SlarPictures& pictures);

// metadata.json's content.
// extra (added, backward compatible): merged into the top level (SAR:
// warnings, noise, point-target measurements).
nlohmann::json slar_metadata(const Scene& scene, const SlarSimulation& sim,
                             const SlarPictures& pictures, const SlarRunInfo& info,
                             const nlohmann::json& extra = nlohmann::json::object());
// The same for a scene whose arrays are not in memory (a streamed run,
// ris/sim/slar_stream.h): `grid` gives the grid and CRS, the elevation range
// of the cells with data is given (+inf, -inf when none).
nlohmann::json slar_metadata(const Scene& grid, float elevation_min_m, float elevation_max_m,
                             const SlarSimulation& sim, const SlarPictures& pictures,
                             const SlarRunInfo& info);

// How each GeoTIFF product is written (metadata, band description, no-data
// value, georeferenced like the scene or not), shared with the streamed run
// (ris/sim/slar_stream.h) so that its files are the same bytes. file: one of
// the .tif names above; img gives the slant-range layout.
struct SlarRasterSpec {
  RasterMetadata metadata;
  std::string band;
  std::optional<double> nodata;
  bool georeferenced = false;
  // An internal mask band instead of a no-data value (every value is valid
  // data: geocoded_grey.tif, where 0 is black).
  bool mask_band = false;
};
SlarRasterSpec slar_raster_spec(const std::string& file, const SlarImage& img);

// The order in which the scene-grid maps (scene_mask.tif,
// local_incidence_deg.tif) are written: that of the azimuth lines for a
// track along a grid axis (a streamed run computes them line by line), top
// down otherwise.
BlockOrder scene_line_order(const Track& track);

// The order a run writes its scene-grid maps in: scene_line_order for lines
// one per cell row or column (fused_slar_applies), top down otherwise (a
// streamed run makes those maps top down, in pass 1m).
BlockOrder scene_maps_order(const Scene& grid, const SlarGeometry& layout);

// The product stems of a SLAR or SAR run (ProductSelection; docs/outputs.md).
const std::vector<std::string_view>& slar_product_stems();

// The calibrated images' stems (ris/image/radiometric_calibration.h):
// "sigma0_slant", "sigma0_slant_db", "beta0_slant", ...
std::string calibrated_product_stem(Backscatter b, bool decibels);
// Whether a run writes the calibrated image `stem`: with info.calibrated
// (--calibrated) as info.products selects; without, only when
// info.products names it. Either way not by default, so a run's folder
// keeps its files.
bool wants_calibrated(const SlarRunInfo& info, std::string_view stem);
// Whether a selection names any calibrated image.
bool names_calibrated(const ProductSelection& selection);
// The calibrated images a run writes (wants_calibrated), into a metadata
// "products" object with their descriptions, and as one task each that
// computes the image from pic's power after fading and calls write(file,
// lines x bins values).
void add_calibrated_descriptions(nlohmann::json& products, const SlarSimulation& sim,
                                 const SlarRunInfo& info);
void add_calibrated_tasks(std::vector<std::function<void()>>& tasks, const SlarSimulation& sim,
                          const SlarPictures& pic, const SlarRunInfo& info,
                          const std::function<void(const std::string&, const float*)>& write);

// Writes the products info.products selects (all by default) with
// info.compression, concurrently (one thread per file at a time).
void write_slar_products(const std::filesystem::path& out_dir, const Scene& scene,
                         const SlarSimulation& sim, const SlarPictures& pictures,
                         const SlarRunInfo& info,
                         const nlohmann::json& extra_metadata = nlohmann::json::object());

}  // namespace ris
