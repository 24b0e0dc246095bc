// The georeferencing of an acquisition-grid product (`ris simulate
// --acquisition`): ground control points in latitude/longitude (EPSG:4326,
// x longitude, y latitude, z the ellipsoidal height), as a Sentinel-1
// measurement GeoTIFF's GCPs and the NISAR geolocation grid give them, so
// gdalwarp and QGIS place the radar-grid rasters on the map (docs/outputs.md,
// "Geolocation of the acquisition-grid products").
//
// The geometry is the product's radar grid with the DEM's heights, as
// `ris topo` computes its latitude/longitude layers (topo_radar_line,
// ris/geometry/topo.h; MODEL.md section 2, the WGS 84 ellipsoid): pixel
// (bin k, line l) of the window is centred on range sample bin0 + k at the
// zero-Doppler time of line line0 + l, and its ground point is rdr2geo of
// that time and range on the DEM (ris/geometry/zero_doppler.h). A GCP sits
// at that pixel's centre (GDAL pixel k + 0.5, line l + 0.5). Where rdr2geo
// finds no ground on the DEM (off it, on no-data postings) the point is
// taken on the ellipsoid raised to flat_height_m (the products use the
// middle of the DEM's height range), so that the grid of points stays whole.
//
// Example:
//   const ris::Georef g = ris::acquisition_georef(acq, dem, window, 0.5 * (h_min + h_max));
//   ris::write_geotiff(path, power.data(), window.bins, window.lines, &g, NAN);
#pragma once

#include <vector>

#include "ris/geometry/topo.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/io/raster_io.h"
#include "ris/sensor/acquisition.h"

namespace ris {

// Up to per_side x per_side points (Sentinel-1 gives ~10 x 21): the
// window's lines and bins that carry them, evenly spread, first and last
// included. 32 rather than the scene products' 20: an airborne track
// wanders, and on the Winnipeg (UAVSAR) product 20 x 20 left a gdalwarp
// -tps 1.04 pixel diagonals off topo's ground at worst, 32 x 32 0.96
// (OverlayAcquisitionCli).
struct AcquisitionTieGrid {
  std::vector<int> lines, bins;  // window indices
};
AcquisitionTieGrid acquisition_tie_grid(const GridWindow& window, int per_side = 32);

// An empty Georef in EPSG:4326 (WKT2), to which the tie lines are added.
Georef acquisition_georef_frame();

// Window line l's tie points, on `dem` (the whole DEM or a window of it that
// holds the line's ground), appended to out.gcps.
void add_acquisition_tie_line(const Acquisition& acq, const EllipsoidalDem& dem,
                              const GridWindow& window, int l, const std::vector<int>& bins,
                              double flat_height_m, Georef& out);

// The whole grid of tie points on a DEM in memory.
Georef acquisition_georef(const Acquisition& acq, const EllipsoidalDem& dem,
                          const GridWindow& window, double flat_height_m, int per_side = 32);

}  // namespace ris
