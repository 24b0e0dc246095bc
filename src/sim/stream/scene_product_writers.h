// Internal: the GeoTIFFs a scene's streamed run writes block by block (rank
// 0), each with the in-memory run's raster spec (slar_raster_spec): the
// scene-grid products with the scene's geotransform, the slant-range ones
// with their GCPs (slant_georef, made once, when first needed), and the
// uncompressed spills of a track off the axes (pass 1m's input).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "ris/image/slant_georef.h"
#include "ris/io/atomic_file.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/scene/scene_stream.h"
#include "ris/sim/run_info.h"
#include "ris/sim/slar_products.h"
#include "ris/sim/slar_simulation.h"

namespace ris::detail {

class SceneProductWriters {
 public:
  // h_mid_m: the slant GCPs' first guess of the terrain height (the
  // scene's mid height).
  SceneProductWriters(StagedDirectory& dir, const SlarRunInfo& info, const SceneStreamReader& in,
                      const SlarSimulation& sim, double h_mid_m)
      : dir_(dir),
        info_(info),
        in_(in),
        sim_(sim),
        h_mid_m_(h_mid_m),
        georef_{in.grid().geotransform(), in.grid().crs_wkt} {}

  template <typename T>
  std::unique_ptr<GeoTiffBlockWriter<T>> open(const std::string& file, int cols, int rows,
                                              ris::BlockOrder order = ris::BlockOrder::top_down) {
    const SlarRasterSpec spec = slar_raster_spec(file, sim_.image);
    auto w = std::make_unique<GeoTiffBlockWriter<T>>(
        dir_.path(file), cols, rows, std::vector<std::string>{spec.band},
        spec.georeferenced ? &georef_ : &slant_georef(), spec.nodata, spec.metadata,
        product_tiff_settings(info_, std::is_floating_point_v<T>), order);
    if (spec.mask_band) w->add_mask_band();
    return w;
  }

  // A spill of one value a sample (lines x samples), uncompressed, in the
  // staging folder.
  template <typename T>
  std::unique_ptr<GeoTiffBlockWriter<T>> open_spill(const char* file) {
    GeoTiffCompression none;
    none.method = "NONE";
    none.overviews = false;
    return std::make_unique<GeoTiffBlockWriter<T>>(
        dir_.path(file), sim_.geometry.samples, sim_.geometry.lines, std::vector<std::string>{file},
        nullptr, std::nullopt, RasterMetadata{}, none);
  }

  // The slant-range products' GCPs, as an in-memory run's (slant_georef).
  const Georef& slant_georef() {
    if (!slant_georef_) {
      slant_georef_ =
          ris::slant_georef(in_.grid(), sim_.track, sim_.image, streamed_elevation(in_), h_mid_m_);
    }
    return *slant_georef_;
  }

  StagedDirectory& dir() { return dir_; }

 private:
  StagedDirectory& dir_;
  const SlarRunInfo& info_;
  const SceneStreamReader& in_;
  const SlarSimulation& sim_;
  double h_mid_m_;
  Georef georef_;
  std::optional<Georef> slant_georef_;
};

}  // namespace ris::detail
