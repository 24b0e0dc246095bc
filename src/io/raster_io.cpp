#include "ris/io/raster_io.h"

#include <cpl_conv.h>
#include <cpl_string.h>
#include <gdal.h>
#include <gdal_utils.h>
#include <ogr_srs_api.h>

#include <png.h>

#include <complex>
#include <stdexcept>
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

template <typename T>
void write_geotiff_masked(const std::filesystem::path& path, const T* data,
                          const std::uint8_t* valid, int cols, int rows, const Georef* georef,
                          const RasterMetadata& metadata, const std::string& band_description,
                          const GeoTiffCompression* compression) {
  RIS_CHECK(cols > 0 && rows > 0);
  GeoTiffBlockWriter<T> writer(path, cols, rows, {band_description}, georef, std::nullopt, metadata,
                               compression != nullptr ? *compression : GeoTiffCompression{});
  writer.add_mask_band();
  writer.write(data, rows, 0, valid);
  writer.close();
}

#define RIS_INSTANTIATE_GEOTIFF(T)                                                                 \
  template void write_geotiff<T>(const std::filesystem::path&, const T*, int, int, const Georef*,  \
                                 std::optional<double>, const RasterMetadata&, const std::string&, \
                                 BlockOrder, const GeoTiffCompression*);                           \
  template void write_geotiff_bands<T>(const std::filesystem::path&,                               \
                                       const std::vector<BandView<T>>&, int, int, const Georef*,   \
                                       std::optional<double>, const RasterMetadata&);              \
  template void write_geotiff_masked<T>(                                                           \
      const std::filesystem::path&, const T*, const std::uint8_t*, int, int, const Georef*,        \
      const RasterMetadata&, const std::string&, const GeoTiffCompression*);
RIS_INSTANTIATE_GEOTIFF(float)
RIS_INSTANTIATE_GEOTIFF(double)
RIS_INSTANTIATE_GEOTIFF(std::uint8_t)
RIS_INSTANTIATE_GEOTIFF(std::uint16_t)
RIS_INSTANTIATE_GEOTIFF(std::int32_t)
RIS_INSTANTIATE_GEOTIFF(std::complex<float>)
#undef RIS_INSTANTIATE_GEOTIFF

namespace {

// GDAL's PNG driver reads the source row by row (bounded memory for a file
// source). PAM is off so no .aux.xml appears beside the temporary name.
void png_copy(const std::filesystem::path& path, GDALDatasetH src, int zlevel) {
  GDALDriverH png = GDALGetDriverByName("PNG");
  RIS_CHECK(png != nullptr);
  RIS_CHECK(zlevel >= 1 && zlevel <= 9);  // GDAL's PNG driver range
  AtomicPath out(path);
  char** options = CSLSetNameValue(nullptr, "ZLEVEL", std::to_string(zlevel).c_str());
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", "NO");
  GDALDatasetH dst =
      GDALCreateCopy(png, out.temp_path().c_str(), src, FALSE, options, nullptr, nullptr);
  CPLSetThreadLocalConfigOption("GDAL_PAM_ENABLED", nullptr);
  CSLDestroy(options);
  if (dst == nullptr) throw InputError(path.string(), "", "cannot write PNG: " + last_gdal_error());
  GDALClose(dst);
  out.commit();
}

void write_png(const std::filesystem::path& path, const std::uint8_t* data, int cols, int rows,
               int channels, int zlevel) {
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
  png_copy(path, handle(src), zlevel);
}
}  // namespace

void write_png_gray_from_raster(const std::filesystem::path& path,
                                const std::filesystem::path& source, int zlevel) {
  GdalDataset src = open_raster(source.string());
  RIS_CHECK(GDALGetRasterCount(handle(src)) == 1 &&
            GDALGetRasterDataType(GDALGetRasterBand(handle(src), 1)) == GDT_Byte);
  if (GDALGetMaskFlags(GDALGetRasterBand(handle(src), 1)) == GMF_PER_DATASET) {
    // A source with a mask band (geocoded_grey.tif): its greytones alone, as
    // write_png_gray, through a virtual copy without the mask (a PNG has no
    // mask band: GDAL would leave a .msk side file).
    char* argv[] = {const_cast<char*>("-of"), const_cast<char*>("VRT"), const_cast<char*>("-mask"),
                    const_cast<char*>("none"), nullptr};
    GDALTranslateOptions* opt = GDALTranslateOptionsNew(argv, nullptr);
    GdalDataset plain(GDALTranslate("", handle(src), opt, nullptr));
    GDALTranslateOptionsFree(opt);
    if (plain == nullptr)
      throw InputError(source.string(), "", "cannot read: " + last_gdal_error());
    png_copy(path, handle(plain), zlevel);
    return;
  }
  png_copy(path, handle(src), zlevel);
}

namespace {

void append_png_bytes(png_structp png, png_bytep data, png_size_t length) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  out->insert(out->end(), data, data + length);
}

// libpng's errors return here by longjmp (its C convention): only C frames
// lie between, and the rows are checked before, so only running out of
// memory gets there.
bool write_png_rows(png_structp png, png_infop info, const std::uint8_t* data, int cols, int rows,
                    int channels, int zlevel) {
  if (setjmp(png_jmpbuf(png))) return false;
  const int colour = channels == 1   ? PNG_COLOR_TYPE_GRAY
                     : channels == 3 ? PNG_COLOR_TYPE_RGB
                                     : PNG_COLOR_TYPE_RGBA;
  png_set_IHDR(png, info, static_cast<png_uint_32>(cols), static_cast<png_uint_32>(rows), 8, colour,
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  png_set_compression_level(png, zlevel);
  png_write_info(png, info);
  const std::size_t stride = static_cast<std::size_t>(cols) * static_cast<std::size_t>(channels);
  for (int r = 0; r < rows; ++r) png_write_row(png, data + static_cast<std::size_t>(r) * stride);
  png_write_end(png, nullptr);
  return true;
}

}  // namespace

std::vector<std::uint8_t> encode_png(const std::uint8_t* data, int cols, int rows, int channels,
                                     int zlevel) {
  RIS_CHECK(channels == 1 || channels == 3 || channels == 4);
  RIS_CHECK(cols > 0 && rows > 0 && zlevel >= 1 && zlevel <= 9);
  // libpng directly rather than GDAL's driver: no row filters (the adaptive
  // choice tries five per row and gains little on speckled images), which
  // makes a 241 x 700 picture several times faster to encode, what a
  // slider's re-render waits for (docs/serve.md).
  std::vector<std::uint8_t> out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  RIS_CHECK(png != nullptr);
  png_infop info = png_create_info_struct(png);
  RIS_CHECK(info != nullptr);
  png_set_write_fn(png, &out, append_png_bytes, nullptr);
  const bool ok = write_png_rows(png, info, data, cols, rows, channels, zlevel);
  png_destroy_write_struct(&png, &info);
  if (!ok) throw std::runtime_error("PNG encoding failed (out of memory?)");
  return out;
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
