#include "ris/io/raster_io.h"

#include <cpl_conv.h>
#include <cpl_string.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <ogr_srs_api.h>

#include <atomic>
#include <type_traits>

#include "ris/io/atomic_file.h"
#include "ris/io/gdal_util.h"
#include "ris/io/geotiff_block_writer.h"
#include "ris/util/error.h"

namespace ris {

template <typename T>
void write_geotiff_bands(const std::filesystem::path& path, const std::vector<BandView<T>>& bands,
                         int cols, int rows, const Georef* georef, std::optional<double> nodata,
                         const RasterMetadata& metadata) {
  RIS_CHECK(!bands.empty() && cols > 0 && rows > 0);
  // The block writer, so a raster written whole and one written in blocks
  // (ris/sim/slar_stream.h) are the same bytes.
  std::vector<std::string> descriptions;
  std::vector<const T*> data;
  for (const BandView<T>& b : bands) {
    descriptions.push_back(b.description);
    data.push_back(b.data);
  }
  GeoTiffBlockWriter<T> writer(path, cols, rows, descriptions, georef, nodata, metadata);
  writer.write(data, rows);
  writer.close();
}

template <typename T>
void write_geotiff(const std::filesystem::path& path, const T* data, int cols, int rows,
                   const Georef* georef, std::optional<double> nodata,
                   const RasterMetadata& metadata, const std::string& band_description,
                   BlockOrder order, const GeoTiffCompression* compression) {
  RIS_CHECK(cols > 0 && rows > 0);
  GeoTiffBlockWriter<T> writer(path, cols, rows, {band_description}, georef, nodata, metadata,
                               compression != nullptr ? *compression : GeoTiffCompression{}, order);
  const bool by_rows = order == BlockOrder::top_down || order == BlockOrder::bottom_up;
  writer.write(data, by_rows ? rows : cols, static_cast<std::size_t>(cols));
  writer.close();
}

#define RIS_INSTANTIATE_GEOTIFF(T)                                                                 \
  template void write_geotiff<T>(const std::filesystem::path&, const T*, int, int, const Georef*,  \
                                 std::optional<double>, const RasterMetadata&, const std::string&, \
                                 BlockOrder, const GeoTiffCompression*);                           \
  template void write_geotiff_bands<T>(const std::filesystem::path&,                               \
                                       const std::vector<BandView<T>>&, int, int, const Georef*,   \
                                       std::optional<double>, const RasterMetadata&);
RIS_INSTANTIATE_GEOTIFF(float)
RIS_INSTANTIATE_GEOTIFF(double)
RIS_INSTANTIATE_GEOTIFF(std::uint8_t)
RIS_INSTANTIATE_GEOTIFF(std::uint16_t)
RIS_INSTANTIATE_GEOTIFF(std::int32_t)
#undef RIS_INSTANTIATE_GEOTIFF

namespace {

// GDAL's PNG driver reads the source row by row (bounded memory for a file
// source). PAM is off so no .aux.xml appears beside the target.
void png_create_copy(const std::string& target, const std::string& named, GDALDatasetH src,
                     int zlevel) {
  GDALDriverH png = GDALGetDriverByName("PNG");
  RIS_CHECK(png != nullptr);
  RIS_CHECK(zlevel >= 1 && zlevel <= 9);  // GDAL's PNG driver range
  char** options = CSLSetNameValue(nullptr, "ZLEVEL", std::to_string(zlevel).c_str());
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", "NO");
  GDALDatasetH dst = GDALCreateCopy(png, target.c_str(), src, FALSE, options, nullptr, nullptr);
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", nullptr);
  CSLDestroy(options);
  if (dst == nullptr) throw InputError(named, "", "cannot write PNG: " + last_gdal_error());
  GDALClose(dst);
}

void png_copy(const std::filesystem::path& path, GDALDatasetH src, int zlevel) {
  AtomicPath out(path);
  png_create_copy(out.temp_path().string(), path.string(), src, zlevel);
  out.commit();
}

// An in-memory dataset over interleaved 8-bit samples (copied in).
GdalDataset byte_mem_dataset(const std::uint8_t* data, int cols, int rows, int channels) {
  ensure_gdal_writers_registered();
  RIS_CHECK(cols > 0 && rows > 0);
  GDALDriverH mem = GDALGetDriverByName("MEM");
  RIS_CHECK(mem != nullptr);
  GdalDataset src(GDALCreate(mem, "", cols, rows, channels, GDT_Byte, nullptr));
  RIS_CHECK(src != nullptr);
  for (int b = 0; b < channels; ++b) {
    GDALRasterBandH band = GDALGetRasterBand(handle(src), b + 1);
    // Interleaved input: pixel stride = channels bytes, line stride = cols*channels.
    CPLErr err = GDALRasterIO(band, GF_Write, 0, 0, cols, rows, const_cast<std::uint8_t*>(data + b),
                              cols, rows, GDT_Byte, channels, cols * channels);
    RIS_CHECK(err == CE_None);
  }
  return src;
}

void write_png(const std::filesystem::path& path, const std::uint8_t* data, int cols, int rows,
               int channels, int zlevel) {
  GdalDataset src = byte_mem_dataset(data, cols, rows, channels);
  png_copy(path, handle(src), zlevel);
}
}  // namespace

void write_png_gray_from_raster(const std::filesystem::path& path,
                                const std::filesystem::path& source, int zlevel) {
  GdalDataset src = open_raster(source.string());
  RIS_CHECK(GDALGetRasterCount(handle(src)) == 1 &&
            GDALGetRasterDataType(GDALGetRasterBand(handle(src), 1)) == GDT_Byte);
  png_copy(path, handle(src), zlevel);
}

std::vector<std::uint8_t> encode_png(const std::uint8_t* data, int cols, int rows, int channels,
                                     int zlevel) {
  RIS_CHECK(channels == 1 || channels == 3 || channels == 4);
  GdalDataset src = byte_mem_dataset(data, cols, rows, channels);
  // A /vsimem/ name of this call's own (callers may run on many threads).
  static std::atomic<std::uint64_t> counter{0};
  const std::string name = "/vsimem/ris-encode-" + std::to_string(counter.fetch_add(1)) + ".png";
  png_create_copy(name, "in-memory PNG", handle(src), zlevel);
  vsi_l_offset length = 0;
  GByte* bytes = VSIGetMemFileBuffer(name.c_str(), &length, TRUE);  // takes ownership
  RIS_CHECK(bytes != nullptr);
  std::vector<std::uint8_t> png(bytes, bytes + length);
  VSIFree(bytes);
  VSIUnlink(name.c_str());
  return png;
}

void write_png_gray(const std::filesystem::path& path, const std::uint8_t* data, int cols, int rows,
                    int zlevel) {
  write_png(path, data, cols, rows, 1, zlevel);
}

void write_png_rgb(const std::filesystem::path& path, const std::uint8_t* rgb, int cols, int rows,
                   int zlevel) {
  write_png(path, rgb, cols, rows, 3, zlevel);
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
