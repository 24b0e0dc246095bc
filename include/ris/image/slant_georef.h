// The georeferencing of a slant-range product: ground control points from
// the run's geometry (ris/geometry/slant_tie_points.h) in the scene's CRS,
// so gdalwarp and QGIS place the radar-grid rasters on the map
// (docs/outputs.md, "Geolocation of the slant-range products").
//
// Example:
//   const ris::Georef g = ris::slant_georef(scene, sim.track, sim.image,
//                                           ris::scene_elevation(scene), h_mid_m);
//   ris::write_geotiff(path, power.data(), img.bins, img.lines, &g, NAN);
#pragma once

#include "ris/geometry/slant_tie_points.h"
#include "ris/image/slar_image.h"
#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"
#include "ris/scene/scene_stream.h"
#include "ris/sensor/track.h"

namespace ris {

// The elevation of a streamed scene's cells, read one cell at a time (the
// same cells as the scene read whole; GDAL's block cache keeps the tiles a
// tie line crosses).
CellElevation streamed_elevation(const SceneStreamReader& in);

// The layout of a slant-range image, for slant_tie_points.
SlantGridLayout slant_grid_layout(const SlarImage& image);

// GCPs (x, y in the scene's CRS, z the terrain height) of the image's tie
// points; fallback_height_m is the terrain off the scene and on no-data
// cells (the products use the middle of the scene's elevation range).
Georef slant_georef(const Scene& grid, const Track& track, const SlarImage& image,
                    const CellElevation& elevation, double fallback_height_m);
// The same for a scene in memory: its cells, and the middle of their
// elevation range as the fallback.
Georef slant_georef(const Scene& scene, const Track& track, const SlarImage& image);

}  // namespace ris
