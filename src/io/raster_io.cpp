#include "ris/io/raster_io.h"

#include <cpl_string.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <type_traits>

#include "ris/io/atomic_file.h"
#include "ris/io/gdal_util.h"
#include "ris/util/error.h"

namespace ris {

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
  else
    static_assert(sizeof(T) == 0, "unsupported raster sample type");
}

void apply_georef(GDALDatasetH ds, const Georef* georef) {
  if (georef == nullptr) return;
  std::array<double, 6> gt = georef->geotransform;
  GDALSetGeoTransform(ds, gt.data());
  if (!georef->crs_wkt.empty()) GDALSetProjection(ds, georef->crs_wkt.c_str());
}

void apply_metadata(GDALDatasetH ds, const RasterMetadata& metadata) {
  for (const auto& [k, v] : metadata) GDALSetMetadataItem(ds, k.c_str(), v.c_str(), nullptr);
}

}  // namespace

template <typename T>
void write_geotiff_bands(const std::filesystem::path& path, const std::vector<BandView<T>>& bands,
                         int cols, int rows, const Georef* georef, std::optional<double> nodata,
                         const RasterMetadata& metadata) {
  ensure_gdal_registered();
  RIS_CHECK(!bands.empty() && cols > 0 && rows > 0);
  AtomicPath out(path);
  GDALDriverH driver = GDALGetDriverByName("GTiff");
  RIS_CHECK(driver != nullptr);
  char** options = nullptr;
  options = CSLSetNameValue(options, "TILED", "YES");
  options = CSLSetNameValue(options, "COMPRESS", "DEFLATE");
  options = CSLSetNameValue(options, "BIGTIFF", "IF_SAFER");
  if (bands.size() > 1) options = CSLSetNameValue(options, "INTERLEAVE", "BAND");
  GDALDatasetH ds = GDALCreate(driver, out.temp_path().c_str(), cols, rows,
                               static_cast<int>(bands.size()), gdal_type<T>(), options);
  CSLDestroy(options);
  if (ds == nullptr)
    throw InputError(path.string(), "", "cannot create GeoTIFF: " + last_gdal_error());
  GdalDataset owner(ds);
  apply_georef(ds, georef);
  apply_metadata(ds, metadata);
  for (size_t b = 0; b < bands.size(); ++b) {
    GDALRasterBandH band = GDALGetRasterBand(ds, static_cast<int>(b + 1));
    if (nodata) GDALSetRasterNoDataValue(band, *nodata);
    if (!bands[b].description.empty()) GDALSetDescription(band, bands[b].description.c_str());
    CPLErr err = GDALRasterIO(band, GF_Write, 0, 0, cols, rows, const_cast<T*>(bands[b].data), cols,
                              rows, gdal_type<T>(), 0, 0);
    if (err != CE_None) throw InputError(path.string(), "", "write failed: " + last_gdal_error());
  }
  owner.reset();  // flush and close before the rename
  out.commit();
}

template <typename T>
void write_geotiff(const std::filesystem::path& path, const T* data, int cols, int rows,
                   const Georef* georef, std::optional<double> nodata,
                   const RasterMetadata& metadata, const std::string& band_description) {
  write_geotiff_bands<T>(path, {BandView<T>{data, band_description}}, cols, rows, georef, nodata,
                         metadata);
}

#define RIS_INSTANTIATE_GEOTIFF(T)                                                                \
  template void write_geotiff<T>(const std::filesystem::path&, const T*, int, int, const Georef*, \
                                 std::optional<double>, const RasterMetadata&,                    \
                                 const std::string&);                                             \
  template void write_geotiff_bands<T>(const std::filesystem::path&,                              \
                                       const std::vector<BandView<T>>&, int, int, const Georef*,  \
                                       std::optional<double>, const RasterMetadata&);
RIS_INSTANTIATE_GEOTIFF(float)
RIS_INSTANTIATE_GEOTIFF(double)
RIS_INSTANTIATE_GEOTIFF(std::uint8_t)
RIS_INSTANTIATE_GEOTIFF(std::uint16_t)
RIS_INSTANTIATE_GEOTIFF(std::int32_t)
#undef RIS_INSTANTIATE_GEOTIFF

namespace {
void write_png(const std::filesystem::path& path, const std::uint8_t* data, int cols, int rows,
               int channels) {
  ensure_gdal_registered();
  RIS_CHECK(cols > 0 && rows > 0);
  GDALDriverH mem = GDALGetDriverByName("MEM");
  GDALDriverH png = GDALGetDriverByName("PNG");
  RIS_CHECK(mem != nullptr && png != nullptr);
  GdalDataset src(GDALCreate(mem, "", cols, rows, channels, GDT_Byte, nullptr));
  RIS_CHECK(src != nullptr);
  for (int b = 0; b < channels; ++b) {
    GDALRasterBandH band = GDALGetRasterBand(handle(src), b + 1);
    // Interleaved input: pixel stride = channels bytes, line stride = cols*channels.
    CPLErr err = GDALRasterIO(band, GF_Write, 0, 0, cols, rows, const_cast<std::uint8_t*>(data + b),
                              cols, rows, GDT_Byte, channels, cols * channels);
    RIS_CHECK(err == CE_None);
  }
  AtomicPath out(path);
  GDALDatasetH dst =
      GDALCreateCopy(png, out.temp_path().c_str(), handle(src), FALSE, nullptr, nullptr, nullptr);
  if (dst == nullptr) throw InputError(path.string(), "", "cannot write PNG: " + last_gdal_error());
  GDALClose(dst);
  out.commit();
}
}  // namespace

void write_png_gray(const std::filesystem::path& path, const std::uint8_t* data, int cols,
                    int rows) {
  write_png(path, data, cols, rows, 1);
}

void write_png_rgb(const std::filesystem::path& path, const std::uint8_t* rgb, int cols, int rows) {
  write_png(path, rgb, cols, rows, 3);
}

RasterF64 read_raster_f64(const std::filesystem::path& path) {
  GdalDataset ds = open_raster(path.string());
  RasterF64 r;
  r.cols = GDALGetRasterXSize(handle(ds));
  r.rows = GDALGetRasterYSize(handle(ds));
  r.bands = GDALGetRasterCount(handle(ds));
  r.data.resize(static_cast<size_t>(r.cols) * r.rows * r.bands);
  for (int b = 0; b < r.bands; ++b) {
    GDALRasterBandH band = GDALGetRasterBand(handle(ds), b + 1);
    if (b == 0) {
      int has = 0;
      double nd = GDALGetRasterNoDataValue(band, &has);
      if (has) r.nodata = nd;
    }
    CPLErr err = GDALRasterIO(band, GF_Read, 0, 0, r.cols, r.rows,
                              r.data.data() + static_cast<size_t>(b) * r.cols * r.rows, r.cols,
                              r.rows, GDT_Float64, 0, 0);
    if (err != CE_None) throw InputError(path.string(), "", "read failed: " + last_gdal_error());
  }
  r.has_geotransform = GDALGetGeoTransform(handle(ds), r.georef.geotransform.data()) == CE_None;
  const char* wkt = GDALGetProjectionRef(handle(ds));
  if (wkt != nullptr) r.georef.crs_wkt = wkt;
  char** md = GDALGetMetadata(handle(ds), nullptr);
  for (int i = 0; md != nullptr && md[i] != nullptr; ++i) {
    char* key = nullptr;
    const char* value = CPLParseNameValue(md[i], &key);
    if (key != nullptr && value != nullptr) r.metadata[key] = value;
    CPLFree(key);
  }
  return r;
}

}  // namespace ris
