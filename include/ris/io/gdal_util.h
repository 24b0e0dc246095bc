// Small helpers around GDAL's C API: one-time driver registration, an owning
// dataset handle, and errors turned into InputError.
#pragma once

#include <gdal.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

class OGRSpatialReference;

namespace ris {

// Registers GDAL's drivers once (thread-safe) and routes GDAL's own error
// messages to spdlog at debug level (ris reports errors itself). For
// opening a raster of any format.
void ensure_gdal_registered();
// Only what writing products and handling CRSs need: the error routing and
// the GTiff, PNG and MEM drivers. Registering every driver costs some 8 ms
// of CPU (docs/performance.md, "Whole process") that a run reading no raster
// (a scene description) need not pay; ensure_gdal_registered adds the rest.
void ensure_gdal_writers_registered();

struct GdalCloser {
  void operator()(void* ds) const {
    if (ds != nullptr) GDALClose(static_cast<GDALDatasetH>(ds));
  }
};
using GdalDataset = std::unique_ptr<void, GdalCloser>;

inline GDALDatasetH handle(const GdalDataset& ds) {
  return static_cast<GDALDatasetH>(ds.get());
}

// Opens a raster for reading; throws InputError naming the file when it is
// missing, unreadable or not a raster.
GdalDataset open_raster(const std::string& path);

// The last GDAL error message, or "unknown GDAL error".
std::string last_gdal_error();

// The message for a write of `out` that failed: GDAL's error and, when the
// disk is full (ENOSPC) or the file-size limit (`ulimit -f`, EFBIG: ris
// ignores SIGXFSZ, ris/io/interrupt_cleanup.h) was reached, which one, the
// room there is and what the file needs (needed_bytes, uncompressed; 0 when
// not known). written: the file being written (its temporary name).
std::string write_failure(const std::filesystem::path& out, const std::filesystem::path& written,
                          std::int64_t needed_bytes);

// The axis-aligned bounds {x0, y0, x1, y1}, in its own CRS, of a raster of
// cols x rows under the geotransform gt: all four corners, so rotated grids
// are covered too.
std::array<double, 4> raster_outline(const std::array<double, 6>& gt, int cols, int rows);

// WKT2 of a CRS, for GDAL options and scene files.
std::string wkt_of(const OGRSpatialReference& srs);

// A north-up target grid for warp_band1: north-west corner, cell size, size.
struct WarpGrid {
  std::string crs_wkt;
  double min_x = 0.0, max_y = 0.0;
  double cell_x = 1.0, cell_y = 1.0;
  int cols = 0, rows = 0;
};

// Warps band 1 of `src` (whose CRS is given as src_wkt, horizontal only, so
// that values are never shifted vertically) onto `grid` with GDAL's warper
// into memory: resampling "near", "bilinear", ...; output type; destination
// no-data ("nan" or a number). The transformation is exact at every cell
// (gdalwarp -et 0). `path` names the source in errors.
GdalDataset warp_band1(GDALDatasetH src, const std::string& src_wkt, const WarpGrid& grid,
                       const std::string& resampling, const std::string& output_type,
                       const std::string& dst_nodata, const std::string& path);

}  // namespace ris
