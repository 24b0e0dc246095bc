#include "ris/image/slant_georef.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace ris {

CellElevation streamed_elevation(const SceneStreamReader& in) {
  return [&in](int row, int col) {
    float z = 0.0f;
    std::uint16_t category = 0;
    std::uint8_t valid = 0;
    in.read(row, 1, col, 1, &z, &category, &valid);
    return valid ? z : std::numeric_limits<float>::quiet_NaN();
  };
}

SlantGridLayout slant_grid_layout(const SlarImage& image) {
  return {image.lines, image.bins, image.range.near_m, image.range.bin_m, image.line_spacing_m};
}

Georef slant_georef(const Scene& grid, const Track& track, const SlarImage& image,
                    const CellElevation& elevation, double fallback_height_m) {
  Georef g;
  g.crs_wkt = grid.crs_wkt;
  for (const TiePoint& t :
       slant_tie_points(grid, track, slant_grid_layout(image), elevation, fallback_height_m)) {
    g.gcps.push_back({t.pixel, t.line, t.x_m, t.y_m, t.height_m});
  }
  return g;
}

Georef slant_georef(const Scene& scene, const Track& track, const SlarImage& image) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (!scene.valid[i]) continue;
    lo = std::min(lo, scene.elevation_m[i]);
    hi = std::max(hi, scene.elevation_m[i]);
  }
  const double mid = lo <= hi ? 0.5 * (double(lo) + double(hi)) : 0.0;
  return slant_georef(scene, track, image, scene_elevation(scene), mid);
}

}  // namespace ris
