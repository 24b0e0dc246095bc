// The products of a PPI simulation, written through StagedDirectory (all or
// nothing; docs/outputs.md, "PPI"):
//
//   ppi_scope.png            greytones, Cartesian scope centred on the radar,
//                            north up (range rings when configured)
//   ppi_scope_power.tif      float32 speckled power on the scope (W); ground
//                            presentation: georeferenced like the scene
//   ppi_scope_mask.tif       uint8 on the scope: 1 shadow, 2 layover, 4 no data
//   bscope.png               greytones, rays (rows, from the scan start
//                            clockwise) x slant-range bins (columns)
//   mean_power_bscope.tif    float32 mean power before speckle (W)
//   speckled_power_bscope.tif float32 power after fading (W)
//   mask_bscope.tif          uint8: 1 shadow, 2 layover, 4 no data
//   metadata.json            inputs, derived quantities, software version
//
// Example:
//   ris::write_ppi_products("out", scene, sim, pictures, info);
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"
#include "ris/sim/ppi_simulation.h"
#include "ris/sim/run_metadata.h"
#include "ris/sim/slar_products.h"

namespace ris {

nlohmann::json ppi_metadata(const Scene& scene, const PpiSimulation& sim, const PpiPictures& pic,
                            const SlarRunInfo& info);
// The same given the scene's summary (a streamed scene, ris/sim/ppi_stream.h):
// sim's and pic's arrays are not read.
nlohmann::json ppi_metadata(const SceneSummary& scene, const PpiSimulation& sim,
                            const PpiPictures& pic, const SlarRunInfo& info);

// The rasters' metadata and the scope's georeferencing (ground presentation).
struct PpiRasterSpecs {
  RasterMetadata bscope;  // the B-scope rasters
  RasterMetadata scope;   // the scope rasters
  Georef georef;          // the scope's, when scope_georeferenced
  bool scope_georeferenced = false;
};
PpiRasterSpecs ppi_raster_specs(const Scene& grid, const PpiSimulation& sim);

// The product stems of a PPI run (ProductSelection; docs/outputs.md).
const std::vector<std::string_view>& ppi_product_stems();

// An upper bound on the disk a PPI run's products take at their largest
// (the free-disk check before a run, ris/util/resource_guard.h), from the
// radar alone: they are sized by its rays, range bins and scope, not by the
// scene. Every file uncompressed (the speckled power barely compresses), in
// whole 256-pixel tiles with a third more for overviews on large rasters:
// the B-scope's scan rays x bins at 4 + 4 + 1 bytes (mean and speckled
// power, mask) and bscope.png, the scope's size^2 pixels (at its largest,
// the slant-range radius) at 4 + 1 (power, mask) and ppi_scope.png, the
// streamed run's two temporary greytone rasters (1 byte a pixel) the PNGs
// are made from, and 1 MiB for metadata.json and the files' headers.
struct PpiProductSize {
  double rays = 0, bins = 0;  // the B-scope (scan rays x range bins)
  double scope_pixels = 0;    // the scope's side
  double bscope_bytes = 0, scope_bytes = 0;
  std::int64_t bytes = 0;  // the whole bound (B-scope, scope, 1 MiB)
};
PpiProductSize ppi_product_size(const RadarParams& radar);

// Writes the products info.products selects (all by default) with
// info.compression, concurrently.
void write_ppi_products(const std::filesystem::path& out_dir, const Scene& scene,
                        const PpiSimulation& sim, const PpiPictures& pic, const SlarRunInfo& info);

}  // namespace ris
