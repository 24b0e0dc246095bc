// Writing rasters through GDAL: GeoTIFF products and PNG pictures.
//
// Every writer is atomic (temporary name, then rename). GeoTIFFs are tiled
// and compressed (ZSTD level 1 unless told: ris/io/geotiff_block_writer.h);
// PNGs are made through GDAL's PNG driver from an
// in-memory dataset.
//
// Example:
//   ris::Georef g{scene.geotransform(), scene.crs_wkt};
//   ris::write_geotiff<float>("power.tif", power.data(), cols, rows, &g, NAN);
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace ris {

struct GeoTiffCompression;  // ris/io/geotiff_block_writer.h

// A ground control point: image position (GDAL pixel / line, 0 at the
// top-left corner of the first pixel) and its ground point (x, y, z in the
// CRS of its Georef).
struct GroundControlPoint {
  double pixel = 0.0, line = 0.0;
  double x = 0.0, y = 0.0, z = 0.0;
};

// Georeferencing of a raster: a GDAL geotransform and a CRS (WKT, may be
// empty); or, when gcps is not empty, ground control points in that CRS
// instead of a geotransform (a raster on the radar's own grid: gdalwarp and
// QGIS place it by them).
struct Georef {
  Georef() = default;
  Georef(const std::array<double, 6>& gt, std::string wkt)
      : geotransform(gt), crs_wkt(std::move(wkt)) {}
  std::array<double, 6> geotransform{0, 1, 0, 0, 0, -1};
  std::string crs_wkt;
  std::vector<GroundControlPoint> gcps;
};

// Key/value metadata written into the file's default metadata domain.
using RasterMetadata = std::map<std::string, std::string>;

// One band of a multi-band raster: data (cols*rows, row-major), a name.
template <typename T>
struct BandView {
  const T* data = nullptr;
  std::string description;
};

// The order in which a GeoTIFF's blocks are written (ris/io/
// geotiff_block_writer.h): rows from the top or the bottom, or columns from
// the left or the right (a scene-grid product of a track along y heading
// north, or along x, computed line by line). The file's tiles are written
// in that order; the pixels are the same whatever the order.
enum class BlockOrder { top_down, bottom_up, left_right, right_left };

// Single-band GeoTIFF of float, double, uint8_t, uint16_t, int32_t or
// std::complex<float> (CFloat32) samples.
// georef may be null (no georeferencing: pixel coordinates); compression
// null: GeoTiffCompression{}.
template <typename T>
void write_geotiff(const std::filesystem::path& path, const T* data, int cols, int rows,
                   const Georef* georef, std::optional<double> nodata = std::nullopt,
                   const RasterMetadata& metadata = {}, const std::string& band_description = "",
                   BlockOrder order = BlockOrder::top_down,
                   const GeoTiffCompression* compression = nullptr);

// A single-band GeoTIFF with an internal per-dataset mask band instead of a
// no-data value (GeoTiffBlockWriter::add_mask_band): valid (cols*rows)
// nonzero where the pixel holds data.
template <typename T>
void write_geotiff_masked(const std::filesystem::path& path, const T* data,
                          const std::uint8_t* valid, int cols, int rows, const Georef* georef,
                          const RasterMetadata& metadata, const std::string& band_description,
                          const GeoTiffCompression* compression = nullptr);

// Multi-band GeoTIFF, every band of type T.
template <typename T>
void write_geotiff_bands(const std::filesystem::path& path, const std::vector<BandView<T>>& bands,
                         int cols, int rows, const Georef* georef,
                         std::optional<double> nodata = std::nullopt,
                         const RasterMetadata& metadata = {});

// PNG zlib level when none is given: 1, measured faster than GDAL's default
// 6 (3x on the standard scene's pictures) and smaller (GDAL's row filters
// leave little for the higher levels; docs/performance.md, "Product
// writing").
inline constexpr int kDefaultPngLevel = 1;

// 8-bit greyscale PNG (0 black, 255 white); zlevel: zlib level 1 (fastest)
// to 9.
void write_png_gray(const std::filesystem::path& path, const std::uint8_t* data, int cols, int rows,
                    int zlevel = kDefaultPngLevel);
// 8-bit greyscale PNG of a one-band Byte raster file (e.g. a GeoTIFF written
// block by block, ris/io/geotiff_block_writer.h): GDAL reads the source row
// by row, so memory stays bounded; the same bytes as write_png_gray of the
// same pixels.
void write_png_gray_from_raster(const std::filesystem::path& path,
                                const std::filesystem::path& source, int zlevel = kDefaultPngLevel);
// 8-bit RGB PNG from interleaved r,g,b samples (cols*rows*3).
void write_png_rgb(const std::filesystem::path& path, const std::uint8_t* rgb, int cols, int rows,
                   int zlevel = kDefaultPngLevel);

// An 8-bit PNG in memory (the HTTP server's images): channels 1 (grey), 3
// (RGB) or 4 (RGBA), interleaved; the same pixels as the writers above, made
// by libpng without row filters (faster; files a little larger).
std::vector<std::uint8_t> encode_png(const std::uint8_t* data, int cols, int rows, int channels,
                                     int zlevel = kDefaultPngLevel);

// A raster read back as float64, for tests and small tools.
struct RasterF64 {
  int cols = 0;
  int rows = 0;
  int bands = 0;
  std::vector<double> data;  // band-major: band b at offset b*cols*rows
  std::optional<double> nodata;
  Georef georef;
  bool has_geotransform = false;
  RasterMetadata metadata;
};
RasterF64 read_raster_f64(const std::filesystem::path& path);

}  // namespace ris
