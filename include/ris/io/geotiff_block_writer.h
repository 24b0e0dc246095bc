// A GeoTIFF written block by block: rows (or columns) arrive in order, a few
// at a time, and only one strip of tiles (tile height x columns per band, or
// rows x tile width) is ever held in memory, so a raster far larger than memory can be written
// (ris/sim/ slar_stream.h writes its products this way).
//
// The file is tiled (256 x 256), compressed and BIGTIFF=IF_SAFER, written to
// a temporary name and renamed into place by close() (ris/io/atomic_file.h):
// a writer destroyed before close() leaves nothing behind.
//
// Every whole-raster writer of ris/io/raster_io.h (write_geotiff,
// write_geotiff_bands) goes through this class too, and the writer always
// hands GDAL one complete strip of tiles at a time and flushes it, so the
// bytes of the file depend only on its pixels, metadata and BlockOrder: a
// raster written in one call and the same raster written in blocks of any
// size in the same order are the same file.
//
// Example:
//   ris::GeoTiffBlockWriter<float> w("power.tif", cols, rows, {"power_w"}, &georef, NAN);
//   for (int r0 = 0; r0 < rows; r0 += 100) {
//     const int n = std::min(100, rows - r0);
//     w.write(block.data(), n);  // n rows x cols
//   }
//   w.close();
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ris/io/raster_io.h"

namespace ris {

// Compression of the tiles (GDAL GTiff creation options). The products use
// the defaults: ZSTD level 1 without a predictor, measured on ris's products
// (docs/performance.md, "Product writing") 1.7x (standard scene) to 4x (a
// 2048 x 2048 scene) faster than DEFLATE level 1 for the same bytes within
// 1% (predictors made the noisy power rasters larger); read by GDAL 2.3 and
// later (QGIS, rasterio, ISCE3). GDAL's compression threads (the bytes do
// not depend on them: tested). Big scene files use ZSTD with the
// floating-point predictor. `ris simulate --compress` chooses others
// (ris/io/compression_preset.h).
struct GeoTiffCompression {
  std::string method = "ZSTD";  // COMPRESS=
  int level = 1;                // ZLEVEL= (DEFLATE) or ZSTD_LEVEL= (ZSTD)
  int predictor = 1;            // PREDICTOR= (1 none, 2 integer, 3 floating point)
  bool all_threads = true;      // NUM_THREADS=ALL_CPUS
  // Internal overviews (halvings until the overview fits in one tile) when
  // the raster's longer side passes kOverviewTilePixels, so a GIS opens a
  // product at any zoom without reading it whole: averaged for power
  // (RIS_UNITS W), nearest for everything else (masks, categories,
  // greytones, angles). `ris simulate --no-overviews` turns them off.
  bool overviews = true;
};

// One tile (256 pixels): a raster that fits in one tile is read whole in one
// block anyway; anything larger gets overviews, as gdaladdo (--minsize 256)
// and QGIS's pyramid dialog would build, so a zoomed-out view reads one
// overview tile instead of every tile of the raster.
inline constexpr int kOverviewTilePixels = 256;

// The unit a band declares (GDAL's unit type, which QGIS and rasterio show),
// so every product carries one without each writer naming it: a single
// band takes the file's RIS_UNITS metadata; otherwise the description's
// suffix says it ("elevation_m" -> m, "mean_power_w" -> W, "..._deg" ->
// deg, "..._db" -> dB); a mask's bits are "bits", a greytone "greytone", a
// category id none ("").
std::string band_unit(const std::string& description, const RasterMetadata& metadata, int bands);

template <typename T>
class GeoTiffBlockWriter {
 public:
  // bands: one description per band (empty strings allowed; at least one
  // band). georef may be null. Throws InputError when the file cannot be
  // created.
  GeoTiffBlockWriter(const std::filesystem::path& path, int cols, int rows,
                     const std::vector<std::string>& band_descriptions, const Georef* georef,
                     std::optional<double> nodata = std::nullopt,
                     const RasterMetadata& metadata = {},
                     const GeoTiffCompression& compression = {},
                     BlockOrder order = BlockOrder::top_down);
  ~GeoTiffBlockWriter();
  GeoTiffBlockWriter(const GeoTiffBlockWriter&) = delete;
  GeoTiffBlockWriter& operator=(const GeoTiffBlockWriter&) = delete;

  // Appends the next `count` rows (top_down: below those written; bottom_up:
  // above them) or columns (left_right / right_left). band_data[b] points at
  // band b's block, row-major, in the raster's own orientation (top row
  // first, left column first): count rows x cols, or rows x count columns
  // with `stride` samples from one row to the next (0: count). Throws
  // InputError on a write failure (a full disk).
  // With a mask band (add_mask_band), `mask` is its block in the same
  // layout: nonzero where the pixels hold data.
  void write(const std::vector<const T*>& band_data, int count, std::size_t stride = 0,
             const std::uint8_t* mask = nullptr);
  // The same for a single-band raster.
  void write(const T* data, int count, std::size_t stride = 0, const std::uint8_t* mask = nullptr) {
    write(std::vector<const T*>{data}, count, stride, mask);
  }

  // Gives the file an internal per-dataset mask band (GDAL's
  // GMF_PER_DATASET: 255 data, 0 none), for a raster whose every value is
  // valid data so that no value can be its no-data (a greytone: 0 is black,
  // not "no pixel"); GDAL, QGIS and rasterio read the mask as the pixels'
  // validity. Before the first write; every write then passes its mask.
  void add_mask_band();

  int written() const { return written_; }  // rows or columns received

  // Writes what is left, closes the file and renames it into place; every
  // row (column) must have been written.
  void close();

 private:
  void flush_strip();
  bool by_rows() const { return order_ == BlockOrder::top_down || order_ == BlockOrder::bottom_up; }
  bool ascending() const {
    return order_ == BlockOrder::top_down || order_ == BlockOrder::left_right;
  }
  // The pixels' bytes, for the message of a failed write.
  std::int64_t uncompressed_bytes() const {
    return std::int64_t{cols_} * rows_ * bands_ * static_cast<std::int64_t>(sizeof(T));
  }

  struct Impl;
  std::unique_ptr<Impl> impl_;
  int cols_ = 0, rows_ = 0, bands_ = 0;
  BlockOrder order_ = BlockOrder::top_down;
  int length_ = 0;  // rows (by rows) or columns
  int tile_ = 256;  // tile height (by rows) or width
  int written_ = 0;
  // The strip being filled: [strip0_, strip0_ + strip_len_) along the axis,
  // per band strip_len_ x cols (by rows) or rows x strip_len_.
  int strip0_ = 0, strip_len_ = 0, strip_filled_ = 0;
  std::vector<std::vector<T>> buffer_;
  std::vector<std::uint8_t> mask_buffer_;  // the mask band's strip (empty: no mask)
};

}  // namespace ris
