// The ground-truth database: a regular grid of elevation, backscatter category
// and validity (MODEL.md section 1).
//
// Conventions: row-major storage, row 0 is the northern edge; x (east) grows
// with column, y (north) grows towards row 0. Cell (r, c) has its centre at
//   x = origin_x_m + (c + 0.5) * dx_m,   y = origin_y_m - (r + 0.5) * dy_m,
// where (origin_x_m, origin_y_m) is the north-west corner of the grid. This
// is GDAL's north-up geotransform {origin_x, dx, 0, origin_y, 0, -dy}.
//
// Example:
//   ris::Scene s = ris::Scene::flat(700, 1000, 6.096, 0.0f, 1);
//   auto [x, y] = s.cell_centre(10, 20);
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace ris {

// Category id stored for no-data cells in category rasters.
inline constexpr std::uint16_t kNoDataCategory = 0xFFFF;
// Categories are 0..kMaxCategory; kNoDataCategory is reserved.
inline constexpr std::uint16_t kMaxCategory = 0xFFFE;

struct Scene {
  int rows = 0;
  int cols = 0;
  double dx_m = 1.0;        // cell size along x (east), metres
  double dy_m = 1.0;        // cell size along y (north), metres
  double origin_x_m = 0.0;  // x of the grid's north-west corner
  double origin_y_m = 0.0;  // y of the grid's north-west corner
  std::string crs_wkt;      // empty when the scene has no CRS (a local frame)

  std::vector<float> elevation_m;       // rows*cols, metres above the datum
  std::vector<std::uint16_t> category;  // rows*cols, backscatter category id
  std::vector<std::uint8_t> valid;      // rows*cols, 1 = data, 0 = no data

  // A flat scene of one category, all cells valid, origin at (0, rows*dy) so
  // that the south-west corner is (0, 0).
  static Scene flat(int rows, int cols, double cell_m, float elevation_m, std::uint16_t category);

  std::size_t size() const {
    return static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  }
  std::size_t index(int row, int col) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(cols) +
           static_cast<std::size_t>(col);
  }
  bool contains(int row, int col) const { return row >= 0 && row < rows && col >= 0 && col < cols; }

  // World coordinates (metres, scene CRS) of a cell's centre.
  std::pair<double, double> cell_centre(int row, int col) const {
    return {origin_x_m + (col + 0.5) * dx_m, origin_y_m - (row + 0.5) * dy_m};
  }
  // Fractional grid coordinates (col, row) of a world point; cell centres are
  // at integer + 0.5.
  std::pair<double, double> grid_from_world(double x_m, double y_m) const {
    return {(x_m - origin_x_m) / dx_m, (origin_y_m - y_m) / dy_m};
  }
  std::pair<double, double> world_from_grid(double col, double row) const {
    return {origin_x_m + col * dx_m, origin_y_m - row * dy_m};
  }

  // GDAL geotransform of this grid (north-up).
  std::array<double, 6> geotransform() const {
    return {origin_x_m, dx_m, 0.0, origin_y_m, 0.0, -dy_m};
  }

  // Bytes one cell takes in memory (elevation + category + validity).
  static constexpr std::size_t bytes_per_cell() {
    return sizeof(float) + sizeof(std::uint16_t) + sizeof(std::uint8_t);
  }

  // Throws InputError when the arrays do not match rows*cols or sizes are not
  // positive; used after building or reading a scene.
  void validate(const std::string& source) const;
};

// The category of every cell of a scene that gives none (an elevation
// raster without a category band; `ris scene import` and `ris scene
// fractal` without --category): grass, id 21 of the shipped
// data/backscatter/generic-terrain.toml, which `ris simulate` then takes as
// the backscatter library (docs/terrain.md, "Categories"). Id 0 of old was
// in no shipped library, so such scenes did not simulate without options.
inline constexpr std::uint16_t kDefaultCategory = 21;
inline constexpr const char* kDefaultCategoryName = "grass";
inline constexpr const char* kDefaultCategoryLibrary = "backscatter/generic-terrain.toml";

// Refuses (InputError naming `source` and `key`) a grid whose memory estimate
// exceeds the limit; the message prints the estimate. The default limit is
// half of physical memory.
void check_scene_fits_in_memory(std::int64_t rows, std::int64_t cols, const std::string& source,
                                const std::string& key);

}  // namespace ris
