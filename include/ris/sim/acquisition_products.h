// The products of a simulation on an acquisition's radar grid
// (ris/sim/acquisition_simulation.h), written into one output folder as a
// whole (StagedDirectory), like a scene run's (ris/sim/slar_products.h) but
// with the radar grid in place of the scene grid:
//
//   slant_range.png          greytones on the product's grid window (rows:
//                            its lines, columns: its range bins)
//   ground_range.png         greytones, ground range over the DEM's mid height
//   mean_power_slant.tif     float32 mean power (W) before speckle
//   speckled_power_slant.tif float32 power after fading (W)
//   mask_slant.tif           uint8: 1 shadow, 2 layover, 4 no data
//   local_incidence.tif      float32 local incidence (degrees), as ris topo's
//   layover_shadow_mask.tif  uint8: 0 none, 1 shadow, 2 layover, 3 both (ris topo's)
//   metadata.json            the acquisition, its grid and window, the Earth
//                            model, the DEM, radar, backscatter, derived values
//
// Every raster's metadata names the grid: RIS_WINDOW_FIRST_LINE,
// RIS_WINDOW_FIRST_BIN, RIS_NEAR_RANGE_M, RIS_RANGE_SPACING_M, ...
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/io/raster_io.h"
#include "ris/sim/acquisition_simulation.h"
#include "ris/sim/run_info.h"
#include "ris/sim/slar_products.h"

namespace ris {

// The metadata every raster of the run carries: the grid window it lies on.
RasterMetadata acquisition_grid_metadata(const AcquisitionSimulation& a);

// A raster product's metadata (the grid's with the product's), band and
// no-data; file: any GeoTIFF of the run. The streamed run
// (ris/sim/acquisition_stream.h) writes the same.
SlarRasterSpec acquisition_raster_spec(const std::string& file, const AcquisitionSimulation& a,
                                       const SlarImage& img);

// The product stems (ProductSelection).
const std::vector<std::string_view>& acquisition_product_stems();

// metadata.json's content. sim: the run's simulation (a.sim, or where it was
// moved to).
nlohmann::json acquisition_metadata(const AcquisitionSimulation& a, const SlarSimulation& sim,
                                    const SlarPictures& pictures, const SlarRunInfo& info);

void write_acquisition_products(const std::filesystem::path& out_dir,
                                const AcquisitionSimulation& a, const SlarSimulation& sim,
                                const SlarPictures& pictures, const SlarRunInfo& info);

}  // namespace ris
