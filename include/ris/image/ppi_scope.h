// The PPI scope: the B-scope (rays x slant-range bins) scan-converted to a
// Cartesian picture centred on the radar, north up, east right, radius
// proportional to slant range (the classic display) or to ground range over
// the site's terrain height (a map-like display, georeferenced like the
// scene) (MODEL.md section 2, "PPI").
//
// Pixel (row, col) of an n x n scope, pixel size p, has its centre at
//   east  = (col + 1/2 - n/2) p,   north = (n/2 - row - 1/2) p
// from the radar; its radius r = hypot(east, north) is the slant range
// (slant) or the ground distance u with R = sqrt(u^2 + D^2), D = H - h_site
// (ground); its azimuth atan2(east, north) picks the ray whose sector holds it
// (nearest ray), R the bin holding it (nearest bin). Pixels outside the scan
// sector or the range window get the fill value.
//
// Example:
//   ris::PpiScopeGrid grid = ris::ppi_scope_grid(radar, sim.bscope.range, depth_m);
//   std::vector<float> scope = ris::to_ppi_scope(bscope_power, grid);
//   ris::draw_range_rings(grey, grid, 5000.0);
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ris/image/slar_image.h"
#include "ris/sensor/radar_params.h"

namespace ris {

struct PpiScopeGrid {
  int size = 0;          // n x n pixels
  double pixel_m = 0.0;  // p
  PpiPresentation presentation = PpiPresentation::slant;
  double depth_m = 0.0;  // D = H - h_site (ground presentation)
  double scan_start_rad = 0.0;
  double ray_spacing_rad = 0.0;
  int rays = 0;  // B-scope rows, ray k covering [start + k dalpha, start + (k+1) dalpha)
  bool full_circle = true;
  SlantRangeBins range;  // B-scope columns
  // Radius (slant or ground metres, per presentation) of a pixel's centre.
  double east_m(int col) const { return (col + 0.5 - 0.5 * size) * pixel_m; }
  double north_m(int row) const { return (0.5 * size - row - 0.5) * pixel_m; }
};

// The grid covering the far range in every direction.
PpiScopeGrid ppi_scope_grid(const RadarParams& radar, const SlantRangeBins& range, int rays,
                            double depth_m);

// Scan conversion of a rays x bins raster (nearest ray and bin); outside the
// sector or range window: NaN (float) or `fill` (bytes).
std::vector<float> to_ppi_scope(std::span<const float> bscope, const PpiScopeGrid& grid);
std::vector<std::uint8_t> to_ppi_scope_nearest(std::span<const std::uint8_t> bscope,
                                               const PpiScopeGrid& grid, std::uint8_t fill);

// The B-scope index (ray * bins + bin) scope pixel (row, col) takes, or -1
// outside the sector or range window (the rule of to_ppi_scope).
std::int64_t ppi_scope_source(const PpiScopeGrid& grid, int row, int col);

// Whether scope pixel (row, col) lies on a range ring every spacing_m
// (spacing_m > 0; the rule of draw_range_rings).
bool on_range_ring(const PpiScopeGrid& grid, int row, int col, double spacing_m);

// Marks range rings every spacing_m (radius in the scope's presentation) on a
// greytone scope: the pixels whose centre lies within half a pixel of a ring
// get `value`.
void draw_range_rings(std::span<std::uint8_t> grey, const PpiScopeGrid& grid, double spacing_m,
                      std::uint8_t value = 255);

}  // namespace ris
