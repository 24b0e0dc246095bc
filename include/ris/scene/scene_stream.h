// A scene raster read a window at a time, for scenes larger than memory
// (ris/sim/slar_stream.h): the grid and georeferencing come from the file's
// header without reading pixels; read() fills caller-provided buffers for
// any rectangle of cells through GDAL's RasterIO, which reads only the tiles
// (or strips) it touches, through GDAL's block cache (bounded by
// bound_gdal_cache()).
//
// The cells are exactly what read_scene (ris/scene/scene_io.h) gives, which is
// built on this reader: a ris scene GeoTIFF (band 1 elevation, band 2
// category, NaN no-data) or any other raster as an elevation model of
// category 0, optionally with categories from a second raster on the same
// grid. Geographic DEMs, which read_scene imports (reprojects) on the fly,
// cannot be streamed: import them first (`ris scene import`).
//
// A tiled GeoTIFF serves any window cheaply; a striped one serves row blocks
// (tracks along y) cheaply, but a block of columns (a track along x) reads
// every strip.
//
// Example:
//   ris::SceneStreamReader in("big.tif");
//   const ris::Scene& grid = in.grid();  // rows, cols, cells, origin, CRS; no arrays
//   std::vector<float> z(rows * grid.cols); std::vector<std::uint16_t> cat(z.size());
//   std::vector<std::uint8_t> ok(z.size());
//   in.read(row0, rows, 0, grid.cols, z.data(), cat.data(), ok.data());
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "ris/scene/scene.h"

namespace ris {

class SceneStreamReader {
 public:
  // Throws InputError naming the file for a missing or unreadable file, a
  // raster that is not north-up, a category raster on another grid, or a
  // DEM that needs importing.
  explicit SceneStreamReader(
      const std::filesystem::path& path,
      const std::optional<std::filesystem::path>& category_path = std::nullopt);
  ~SceneStreamReader();
  SceneStreamReader(const SceneStreamReader&) = delete;
  SceneStreamReader& operator=(const SceneStreamReader&) = delete;

  // The grid: rows, cols, cell size, origin and CRS; its arrays are empty.
  const Scene& grid() const { return grid_; }
  const std::string& path() const { return path_; }
  // Whether the file holds categories (a ris scene or a category raster).
  bool has_categories() const;
  // The elevation band's block size (tile or strip), cells.
  int block_cols() const { return block_cols_; }
  int block_rows() const { return block_rows_; }

  // Reads rows [row0, row0 + rows) x columns [col0, col0 + cols) into
  // row-major buffers of rows x cols: elevation (0 where no data), category
  // (kNoDataCategory where no data), validity (1 data, 0 no data). Throws
  // InputError for a read failure or a category that is not an integer in
  // 0..kMaxCategory (naming its global column and row).
  void read(int row0, int rows, int col0, int cols, float* elevation_m, std::uint16_t* category,
            std::uint8_t* valid) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
  Scene grid_;
  int block_cols_ = 0, block_rows_ = 0;
};

// Caps GDAL's block cache (GDAL_CACHEMAX) at max_bytes unless the user set
// GDAL_CACHEMAX in the environment: GDAL's default is 5% of physical memory,
// more than a streamed run needs. Returns the cap in force.
std::int64_t bound_gdal_cache(std::int64_t max_bytes);

}  // namespace ris
