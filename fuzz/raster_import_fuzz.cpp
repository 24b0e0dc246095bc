// Fuzz harness: a scene or DEM raster as `ris simulate --scene` loads it
// (ris/scene/scene_source.h: a ris scene GeoTIFF, or any DEM that GDAL reads,
// imported). The corpus holds small GeoTIFFs; the fuzzer mutates their
// bytes, so the headers, tags and georeferencing GDAL hands ris are hostile.
// Rasters over a million cells are refused before reading (resource bound of
// the harness, not of ris).
#include <gdal_priv.h>

#include "fuzz_input.h"
#include "ris/scene/scene_source.h"
#include "ris/util/error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ris::fuzz::quiet_logs();
  static const bool gdal = [] {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);
    return true;
  }();
  (void)gdal;
  const std::string path = ris::fuzz::write_input(ris::fuzz::as_text(data, size), ".tif");
  {
    GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
    if (ds == nullptr) return 0;
    const double cells = static_cast<double>(GDALGetRasterXSize(ds)) * GDALGetRasterYSize(ds);
    GDALClose(ds);
    if (cells > 1e6) return 0;
  }
  try {
    (void)ris::load_scene_source(path);
  } catch (const ris::InputError&) {
  }
  return 0;
}
