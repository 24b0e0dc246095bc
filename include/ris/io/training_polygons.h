// Training polygons for supervised classification (docs/classify.md):
// every polygon of a vector file GDAL/OGR reads (GeoJSON, GeoPackage,
// Shapefile, ...), burnt into an image's pixel grid with the integer value
// of its category attribute (1..255, a ris category id).
//
// GDALRasterizeLayers burns a polygon into the pixels whose centres lie
// inside it, reprojecting from the layer's CRS to the image's when they
// differ; where polygons overlap, the later one wins. Every layer of the
// file is read.
//
// Example:
//   ris::TrainingPixels t = ris::rasterize_training_polygons(
//       "training.geojson", "category", img.georef, img.cols, img.rows);
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ris/io/raster_io.h"

namespace ris {

struct TrainingPixels {
  std::vector<std::uint8_t> codes;             // rows*cols: the category, 0 outside
  std::size_t features = 0;                    // polygons read
  std::map<std::uint8_t, std::size_t> pixels;  // per category: pixels burnt
};

// Throws InputError naming `path` and `attribute` when: the file is missing
// or not a vector file; it has no features; a layer lacks the attribute; a
// feature's value is not an integer 1..255 (its feature id is named); or
// no polygon covers a pixel centre of the image (its bounds and the
// polygons' are given). georef: the image's geotransform and CRS, or its
// ground control points (a raster on the radar's grid) and their CRS.
TrainingPixels rasterize_training_polygons(const std::string& path, const std::string& attribute,
                                           const Georef& georef, int cols, int rows);

}  // namespace ris
