// Tie points of a slant-range image: where a grid of (azimuth line, slant
// range) positions of the image lands on the terrain, so that its products
// carry GCPs a GIS can warp them with (gdalwarp, QGIS; docs/outputs.md,
// "Geolocation of the slant-range products").
//
// The geometry is the run's (MODEL.md section 2, flat Earth): line
// coordinate L (GDAL's, 0 at the top edge of line 0) is the along-track
// position s = L ds, pixel coordinate P (0 at the near edge of bin 0) the
// slant range R = R_near + P dr, and the ground point is the nearest point
// of the zero-Doppler line at s whose slant range is R:
// R^2 = u^2 + (H - h(u))^2, h the elevation of the scene cell under the
// point (as geocoding takes it: ris/image/geocode.h). The line is walked
// outward from the track at half a cell and the first crossing of R is
// interpolated linearly between the two samples around it. Off the scene,
// on no-data cells, or where R is never reached inside it, the terrain is
// taken flat at the reference height (the ground-range products' h_ref).
//
// Example:
//   const auto tie = ris::slant_tie_points(scene, track, layout, ris::scene_elevation(scene),
//                                          h_ref_m);
#pragma once

#include <functional>
#include <vector>

#include "ris/scene/scene.h"
#include "ris/sensor/track.h"

namespace ris {

// The slant-range image's layout: lines x bins, the near edge of bin 0, the
// bin size and the azimuth line spacing (ris/image/slar_image.h).
struct SlantGridLayout {
  int lines = 0, bins = 0;
  double near_range_m = 0.0, range_bin_m = 0.0, line_spacing_m = 0.0;
};

// One tie point: image position (GDAL pixel / line, edges at integers) and
// its ground point in the scene's coordinates and height.
struct TiePoint {
  double pixel = 0.0, line = 0.0;
  double x_m = 0.0, y_m = 0.0, height_m = 0.0;
};

// Elevation of scene cell (row, col), metres; NaN where it has no data.
using CellElevation = std::function<float(int row, int col)>;

// The elevation of an in-memory scene's cells.
CellElevation scene_elevation(const Scene& scene);

// Default: up to 20 x 20 points, as the ~10 x 21 grid of a Sentinel-1
// product's GCPs, enough for GDAL's polynomial or thin-plate-spline fit.
inline constexpr int kMaxTiePointsPerSide = 20;

// A grid of up to per_side x per_side tie points, including the image's
// edges (pixel 0 and bins, line 0 and lines), line by line, near range
// first. A position whose slant range is shorter than the sensor's height
// above the reference has no ground point and is left out. grid: the
// scene's layout (rows, cols, cells, origin; its arrays are not used).
std::vector<TiePoint> slant_tie_points(const Scene& grid, const Track& track,
                                       const SlantGridLayout& layout,
                                       const CellElevation& elevation, double reference_height_m,
                                       int per_side = kMaxTiePointsPerSide);

}  // namespace ris
