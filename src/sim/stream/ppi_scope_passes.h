// Internal: the passes of a streamed PPI after its rays (rank 0), each
// reading the B-scope back from the staging folder: pass 1b, the exact
// median mean power (the auto greytone reference); pass 2, the B-scope's
// greytones (bscope.png); pass 2b, the scope a strip of rows at a time
// (each pixel's B-scope source, per ray the bins the strip takes read back
// as one span; power, mask and greytones as render_ppi).
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "ris/image/greytone.h"
#include "ris/io/atomic_file.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/sim/ppi_products.h"
#include "ris/sim/ppi_simulation.h"
#include "ris/sim/run_info.h"
#include "ris/util/rank_select.h"

namespace ris::detail {

// A PPI product written block by block: NaN no-data for floats, the run's
// compression.
template <typename T>
std::unique_ptr<GeoTiffBlockWriter<T>> ppi_product_writer(
    StagedDirectory& dir, const SlarRunInfo& info, const std::string& file, int cols, int rows,
    const RasterMetadata& meta, const std::string& band, const Georef* georef) {
  return std::make_unique<GeoTiffBlockWriter<T>>(
      dir.path(file), cols, rows, std::vector<std::string>{band}, georef,
      std::is_floating_point_v<T> ? std::optional<double>(std::numeric_limits<double>::quiet_NaN())
                                  : std::nullopt,
      meta, product_tiff_settings(info, std::is_floating_point_v<T>));
}

// What the passes read back: the B-scope in dir, rays at a time.
struct PpiReadback {
  StagedDirectory& dir;
  const PpiSimulation& sim;
  const SlarRunInfo& info;
  int bins = 0, scan_rays = 0;
  int readback_rays = 1;
};

// Pass 1b: the median of the valid mean powers counted in pass 1 (power,
// some counted), refined over mean_power_bscope.tif.
double ppi_median_mean_power(const PpiReadback& p, FloatRankSelect& power);
// Pass 2: bscope.png.
void ppi_bscope_picture(const PpiReadback& p, const GreytoneMap& map);
// Pass 2b: ppi_scope_power.tif, ppi_scope_mask.tif and ppi_scope.png.
void ppi_scope_picture(const PpiReadback& p, const GreytoneMap& map, const PpiRasterSpecs& specs);

}  // namespace ris::detail
