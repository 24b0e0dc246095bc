#include "ris/io/geotiff_block_writer.h"

#include <cpl_error.h>
#include <cpl_string.h>
#include <gdal.h>

#include <algorithm>
#include <complex>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "ris/io/atomic_file.h"
#include "ris/io/gdal_util.h"
#include "ris/util/error.h"

namespace ris {

std::string band_unit(const std::string& description, const RasterMetadata& metadata, int bands) {
  const auto units = metadata.find("RIS_UNITS");
  if (bands == 1 && units != metadata.end()) return units->second;
  const std::string name = description.substr(0, description.find(' '));
  const auto ends_with = [&name](const std::string& tail) {
    return name.size() > tail.size() &&
           name.compare(name.size() - tail.size(), tail.size(), tail) == 0;
  };
  if (name.find("mask") != std::string::npos) return "bits";
  if (name.find("grey") != std::string::npos) return "greytone";
  if (ends_with("_m")) return "m";
  if (ends_with("_w")) return "W";
  if (ends_with("_deg")) return "deg";
  if (ends_with("_db")) return "dB";
  return "";
}

namespace {

template <typename T>
constexpr GDALDataType gdal_type() {
  if constexpr (std::is_same_v<T, float>)
    return GDT_Float32;
  else if constexpr (std::is_same_v<T, double>)
    return GDT_Float64;
  else if constexpr (std::is_same_v<T, std::uint8_t>)
    return GDT_Byte;
  else if constexpr (std::is_same_v<T, std::uint16_t>)
    return GDT_UInt16;
  else if constexpr (std::is_same_v<T, std::int32_t>)
    return GDT_Int32;
  else if constexpr (std::is_same_v<T, std::complex<float>>)
    return GDT_CFloat32;  // single-look complex images (ris/sim/sar_quad_pol.h)
  else
    static_assert(sizeof(T) == 0, "unsupported raster sample type");
}

}  // namespace

template <typename T>
struct GeoTiffBlockWriter<T>::Impl {
  explicit Impl(const std::filesystem::path& path) : out(path) {}
  AtomicPath out;
  GdalDataset ds;
  bool overviews = false;  // build them at close()
  std::string resampling;  // "AVERAGE" or "NEAREST"
};

namespace {

// Overview factors 2, 4, 8, ... until the overview fits in one 256-pixel
// tile (gdaladdo's default levels, its --minsize 256).
std::vector<int> overview_levels(int cols, int rows) {
  std::vector<int> levels;
  const int side = std::max(cols, rows);
  for (int f = 2; f < 2 * side; f *= 2) {
    levels.push_back(f);
    if ((side + f - 1) / f <= kOverviewTilePixels) break;
  }
  return levels;
}

// The GCPs of a raster on the radar's grid (GeoTIFF's ModelTiepointTag,
// one tie point each), in the Georef's CRS.
void set_gcps(GDALDatasetH ds, const Georef& georef) {
  std::vector<GDAL_GCP> gcps(georef.gcps.size());
  std::vector<std::string> ids(georef.gcps.size());
  for (std::size_t i = 0; i < gcps.size(); ++i) {
    const GroundControlPoint& g = georef.gcps[i];
    ids[i] = std::to_string(i + 1);
    gcps[i].pszId = ids[i].data();
    gcps[i].pszInfo = const_cast<char*>("");
    gcps[i].dfGCPPixel = g.pixel;
    gcps[i].dfGCPLine = g.line;
    gcps[i].dfGCPX = g.x;
    gcps[i].dfGCPY = g.y;
    gcps[i].dfGCPZ = g.z;
  }
  GDALSetGCPs(ds, static_cast<int>(gcps.size()), gcps.data(), georef.crs_wkt.c_str());
}

}  // namespace

template <typename T>
GeoTiffBlockWriter<T>::GeoTiffBlockWriter(const std::filesystem::path& path, int cols, int rows,
                                          const std::vector<std::string>& band_descriptions,
                                          const Georef* georef, std::optional<double> nodata,
                                          const RasterMetadata& metadata,
                                          const GeoTiffCompression& compression, BlockOrder order)
    : impl_(std::make_unique<Impl>(path)),
      cols_(cols),
      rows_(rows),
      bands_(static_cast<int>(band_descriptions.size())),
      order_(order) {
  ensure_gdal_writers_registered();
  RIS_CHECK(bands_ > 0 && cols > 0 && rows > 0);
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  RIS_CHECK(driver != nullptr);
  char** options = nullptr;
  options = CSLSetNameValue(options, "TILED", "YES");
  options = CSLSetNameValue(options, "COMPRESS", compression.method.c_str());
  if (compression.method == "DEFLATE" || compression.method == "ZSTD") {
    options = CSLSetNameValue(options, compression.method == "ZSTD" ? "ZSTD_LEVEL" : "ZLEVEL",
                              std::to_string(compression.level).c_str());
  }
  if (compression.predictor != 1)
    options = CSLSetNameValue(options, "PREDICTOR", std::to_string(compression.predictor).c_str());
  if (compression.all_threads) options = CSLSetNameValue(options, "NUM_THREADS", "ALL_CPUS");
  options = CSLSetNameValue(options, "BIGTIFF", "IF_SAFER");
  if (bands_ > 1) options = CSLSetNameValue(options, "INTERLEAVE", "BAND");
  GDALDatasetH ds = GDALCreate(driver, impl_->out.temp_path().c_str(), cols, rows, bands_,
                               gdal_type<T>(), options);
  CSLDestroy(options);
  if (ds == nullptr)
    throw InputError(path.string(), "", "cannot create GeoTIFF: " + last_gdal_error());
  impl_->ds.reset(ds);
  impl_->overviews = compression.overviews && std::max(cols, rows) > kOverviewTilePixels;
  const auto units = metadata.find("RIS_UNITS");
  impl_->resampling = units != metadata.end() && units->second == "W" ? "AVERAGE" : "NEAREST";
  if (georef != nullptr && !georef->gcps.empty()) {
    set_gcps(ds, *georef);
  } else if (georef != nullptr) {
    std::array<double, 6> gt = georef->geotransform;
    GDALSetGeoTransform(ds, gt.data());
    if (!georef->crs_wkt.empty()) GDALSetProjection(ds, georef->crs_wkt.c_str());
  }
  for (const auto& [k, v] : metadata) GDALSetMetadataItem(ds, k.c_str(), v.c_str(), nullptr);
  for (int b = 0; b < bands_; ++b) {
    GDALRasterBandH band = GDALGetRasterBand(ds, b + 1);
    if (nodata) GDALSetRasterNoDataValue(band, *nodata);
    const std::string& d = band_descriptions[static_cast<std::size_t>(b)];
    if (!d.empty()) GDALSetDescription(band, d.c_str());
    const std::string unit = band_unit(d, metadata, bands_);
    if (!unit.empty()) GDALSetRasterUnitType(band, unit.c_str());
  }
  int bx = 0, by = 0;
  GDALGetBlockSize(GDALGetRasterBand(ds, 1), &bx, &by);
  length_ = by_rows() ? rows_ : cols_;
  tile_ = std::max(1, by_rows() ? by : bx);
  // The first strip: tiles are aligned from row (column) 0, so descending
  // order starts with the last, possibly partial, strip.
  const int n_strips = (length_ + tile_ - 1) / tile_;
  strip0_ = ascending() ? 0 : (n_strips - 1) * tile_;
  strip_len_ = std::min(tile_, length_ - strip0_);
  const std::size_t across = static_cast<std::size_t>(by_rows() ? cols_ : rows_);
  buffer_.resize(static_cast<std::size_t>(bands_));
  for (auto& b : buffer_) b.resize(static_cast<std::size_t>(std::min(tile_, length_)) * across);
}

template <typename T>
GeoTiffBlockWriter<T>::~GeoTiffBlockWriter() = default;

template <typename T>
void GeoTiffBlockWriter<T>::add_mask_band() {
  RIS_CHECK(impl_->ds != nullptr && written_ == 0 && mask_buffer_.empty());
  // Inside the .tif (GDAL 3.6 would otherwise write a .msk side file).
  CPLSetThreadLocalConfigOption("GDAL_TIFF_INTERNAL_MASK", "YES");
  const CPLErr err = GDALCreateDatasetMaskBand(handle(impl_->ds), GMF_PER_DATASET);
  CPLSetThreadLocalConfigOption("GDAL_TIFF_INTERNAL_MASK", nullptr);
  if (err != CE_None) {
    throw InputError(impl_->out.final_path().string(), "",
                     "cannot create the mask band: " + last_gdal_error());
  }
  mask_buffer_.resize(buffer_.front().size());
}

namespace {

// Lines [in_block, in_block + n) of a block into lines [in_strip, ...) of
// a strip buffer: whole rows (by rows, `w` columns) or n columns of every
// one of `rows` rows (strip width w).
template <typename V>
void copy_lines(V* dst, const V* src, bool by_rows, int in_strip, int in_block, int n, int rows,
                std::size_t w, std::size_t stride) {
  if (by_rows) {
    for (int r = 0; r < n; ++r)
      std::memcpy(dst + static_cast<std::size_t>(in_strip + r) * w,
                  src + static_cast<std::size_t>(in_block + r) * stride, w * sizeof(V));
  } else {
    for (int r = 0; r < rows; ++r)
      std::memcpy(dst + static_cast<std::size_t>(r) * w + static_cast<std::size_t>(in_strip),
                  src + static_cast<std::size_t>(r) * stride + static_cast<std::size_t>(in_block),
                  static_cast<std::size_t>(n) * sizeof(V));
  }
}

}  // namespace

template <typename T>
void GeoTiffBlockWriter<T>::write(const std::vector<const T*>& band_data, int count,
                                  std::size_t stride, const std::uint8_t* mask) {
  RIS_CHECK(impl_->ds != nullptr);
  RIS_CHECK(static_cast<int>(band_data.size()) == bands_);
  RIS_CHECK((mask != nullptr) == !mask_buffer_.empty());
  RIS_CHECK(count >= 0 && written_ + count <= length_);
  if (stride == 0)
    stride = by_rows() ? static_cast<std::size_t>(cols_) : static_cast<std::size_t>(count);
  // The block covers [lo, lo + count) along the axis.
  const int lo = ascending() ? written_ : length_ - written_ - count;
  int done = 0;  // lines of the block consumed, in arrival order
  while (done < count) {
    const int room = strip_len_ - strip_filled_;
    const int n = std::min(room, count - done);
    // The n lines of the block taken now, [a, a + n) along the axis.
    const int a = ascending() ? lo + done : lo + count - done - n;
    const int in_block = a - lo;       // offset in the block
    const int in_strip = a - strip0_;  // offset in the strip
    const std::size_t w = static_cast<std::size_t>(by_rows() ? cols_ : strip_len_);
    for (int b = 0; b < bands_; ++b) {
      copy_lines(buffer_[static_cast<std::size_t>(b)].data(),
                 band_data[static_cast<std::size_t>(b)], by_rows(), in_strip, in_block, n, rows_, w,
                 stride);
    }
    if (mask != nullptr)
      copy_lines(mask_buffer_.data(), mask, by_rows(), in_strip, in_block, n, rows_, w, stride);
    strip_filled_ += n;
    written_ += n;
    done += n;
    if (strip_filled_ == strip_len_) flush_strip();
  }
}

// One complete strip of tiles per RasterIO, flushed at once: the same GDAL
// calls whatever block sizes the caller used, hence the same bytes.
template <typename T>
void GeoTiffBlockWriter<T>::flush_strip() {
  if (strip_filled_ == 0) return;
  RIS_CHECK(strip_filled_ == strip_len_);
  GDALDatasetH ds = handle(impl_->ds);
  const int x0 = by_rows() ? 0 : strip0_, y0 = by_rows() ? strip0_ : 0;
  const int w = by_rows() ? cols_ : strip_len_, h = by_rows() ? strip_len_ : rows_;
  for (int b = 0; b < bands_; ++b) {
    GDALRasterBandH band = GDALGetRasterBand(ds, b + 1);
    const CPLErr err =
        GDALRasterIO(band, GF_Write, x0, y0, w, h, buffer_[static_cast<std::size_t>(b)].data(), w,
                     h, gdal_type<T>(), 0, 0);
    if (err != CE_None) {
      throw InputError(
          impl_->out.final_path().string(), "",
          write_failure(impl_->out.final_path(), impl_->out.temp_path(), uncompressed_bytes()));
    }
  }
  if (!mask_buffer_.empty()) {
    // GDAL's mask values: 255 data, 0 none.
    for (std::uint8_t& m : mask_buffer_) m = m != 0 ? 255 : 0;
    if (GDALRasterIO(GDALGetMaskBand(GDALGetRasterBand(ds, 1)), GF_Write, x0, y0, w, h,
                     mask_buffer_.data(), w, h, GDT_Byte, 0, 0) != CE_None) {
      throw InputError(
          impl_->out.final_path().string(), "",
          write_failure(impl_->out.final_path(), impl_->out.temp_path(), uncompressed_bytes()));
    }
  }
  CPLErrorReset();
  GDALFlushCache(ds);
  if (CPLGetLastErrorType() == CE_Failure || CPLGetLastErrorType() == CE_Fatal) {
    throw InputError(
        impl_->out.final_path().string(), "",
        write_failure(impl_->out.final_path(), impl_->out.temp_path(), uncompressed_bytes()));
  }
  // The next strip.
  strip_filled_ = 0;
  if (ascending()) {
    strip0_ += strip_len_;
  } else {
    strip0_ -= tile_;
  }
  strip_len_ = strip0_ >= 0 && strip0_ < length_ ? std::min(tile_, length_ - strip0_) : 0;
}

template <typename T>
void GeoTiffBlockWriter<T>::close() {
  RIS_CHECK(impl_->ds != nullptr);
  RIS_CHECK(written_ == length_);
  CPLErrorReset();
  if (impl_->overviews) {
    std::vector<int> levels = overview_levels(cols_, rows_);
    if (!levels.empty() && GDALBuildOverviews(handle(impl_->ds), impl_->resampling.c_str(),
                                              static_cast<int>(levels.size()), levels.data(), 0,
                                              nullptr, nullptr, nullptr) != CE_None) {
      throw InputError(impl_->out.final_path().string(), "",
                       "cannot build overviews: " + last_gdal_error());
    }
  }
  GDALClose(impl_->ds.release());
  if (CPLGetLastErrorType() == CE_Failure || CPLGetLastErrorType() == CE_Fatal) {
    throw InputError(
        impl_->out.final_path().string(), "",
        write_failure(impl_->out.final_path(), impl_->out.temp_path(), uncompressed_bytes()));
  }
  impl_->out.commit();
  buffer_.clear();
}

template class GeoTiffBlockWriter<float>;
template class GeoTiffBlockWriter<double>;
template class GeoTiffBlockWriter<std::uint8_t>;
template class GeoTiffBlockWriter<std::uint16_t>;
template class GeoTiffBlockWriter<std::int32_t>;
template class GeoTiffBlockWriter<std::complex<float>>;

}  // namespace ris
