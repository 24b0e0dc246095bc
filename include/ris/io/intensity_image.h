// An image to measure or compare, read as intensity (power) from any GDAL
// raster band or from the SLC layer of a NISAR/UAVSAR RSLC product
// (docs/quality.md, "Inputs").
//
//   path                     a GeoTIFF, PNG, ... (band `band`, from 1), or
//   PRODUCT.h5               its first SLC layer (science/<band>/SLC/swaths/
//                            frequencyA/<pol>), or the `band`-th one, or
//   HDF5:"PRODUCT.h5"://...  any subdataset GDAL names
//
// Pixel scale: complex samples are |z|^2; otherwise `scale` says what the
// values are (auto: floating point = power, integers = amplitude, as GDAL
// readers of SAR products and ris's own products store them).
// Non-finite values and the band's no-data value become NaN (no data).
#pragma once

#include <string>
#include <vector>

#include "ris/io/raster_io.h"

namespace ris {

enum class PixelScale { automatic, power, amplitude, db };

struct IntensityImage {
  std::string source;  // as opened (the subdataset for a product)
  int cols = 0, rows = 0;
  std::vector<float> intensity;  // rows x cols; NaN: no data
  std::string read_as;           // "complex |z|^2", "power", "amplitude^2", "10^(dB/10)"
  Georef georef;  // a geotransform and CRS, or else the raster's GCPs (if any) and their CRS
  bool has_geotransform = false;
  RasterMetadata metadata;  // the dataset's default-domain items
};

// Throws InputError naming the path (missing, not a raster, no such band or
// layer, a bad scale name).
IntensityImage read_intensity_image(const std::string& path, int band = 1,
                                    PixelScale scale = PixelScale::automatic);

// The raster at `path` (band 1) resampled bilinearly onto `grid`'s pixels
// (GDAL's warper, exact transformation). InputError when either lacks a
// geotransform and CRS, or grid is rotated.
IntensityImage read_intensity_image_on_grid(const std::string& path, int band, PixelScale scale,
                                            const IntensityImage& grid);

PixelScale parse_pixel_scale(const std::string& text, const std::string& option);

}  // namespace ris
