#include "ris/io/intensity_image.h"

#include <fmt/format.h>
#include <gdal.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>

#include "ris/io/gdal_util.h"
#include "ris/io/safe_paths.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"

namespace ris {

namespace {

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The `index`-th (from 1) SLC layer of a NISAR/UAVSAR RSLC product: a
// subdataset under .../SLC/swaths/frequency?/ named by a polarisation.
std::string product_layer(const std::string& path, int index) {
  // The container has no bands of its own: opened as a dataset, not a raster.
  const GdalDataset ds(GDALOpenEx(path.c_str(), GDAL_OF_READONLY, nullptr, nullptr, nullptr));
  if (!ds) throw InputError(path, "", "GDAL cannot open it: " + last_gdal_error());
  char** subs = GDALGetMetadata(handle(ds), "SUBDATASETS");
  int seen = 0;
  std::string names;
  for (int i = 0; subs != nullptr && subs[i] != nullptr; ++i) {
    const std::string item = subs[i];
    const auto eq = item.find('=');
    if (eq == std::string::npos || item.find("_NAME=") == std::string::npos) continue;
    const std::string name = item.substr(eq + 1);
    const auto slash = name.rfind('/');
    const std::string leaf = slash == std::string::npos ? name : name.substr(slash + 1);
    const bool pol = leaf.size() == 2 && (leaf[0] == 'H' || leaf[0] == 'V') &&
                     (leaf[1] == 'H' || leaf[1] == 'V');
    if (!pol || name.find("/SLC/swaths/frequency") == std::string::npos) continue;
    names += (names.empty() ? "" : ", ") + leaf;
    if (++seen == index) return name;
  }
  throw InputError(
      path, "band",
      seen == 0 ? std::string("no SLC layer (science/*/SLC/swaths/frequency*/"
                              "<polarisation>) in this HDF5 file")
                : fmt::format("layer {} asked for, the product has {} ({})", index, seen, names));
}

// Band b's values as intensity into img (whose cols and rows are set), by the
// rules of the header.
void fill_intensity(GDALRasterBandH b, PixelScale scale, const std::string& path,
                    IntensityImage& img) {
  // The size the file declares, against the resource guard before anything
  // is allocated (a small HDF5 file may declare a huge never-written
  // dataset): 4 bytes a pixel of intensity and 8 of what is read (two
  // floats, or a double).
  const std::string layer = img.source == path ? "" : img.source;  // an HDF5 dataset
  const std::int64_t pixels = checked_mul(img.cols, img.rows, path, layer);
  require_memory(checked_mul(pixels, 12, path, layer), path, layer,
                 fmt::format("reading the {} x {} image", img.cols, img.rows));
  const auto n = static_cast<std::size_t>(pixels);
  const GDALDataType type = GDALGetRasterDataType(b);
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(b, &has_nodata);
  img.intensity.resize(n);
  if (GDALDataTypeIsComplex(type)) {
    std::vector<float> iq(2 * n);
    if (GDALRasterIO(b, GF_Read, 0, 0, img.cols, img.rows, iq.data(), img.cols, img.rows,
                     GDT_CFloat32, 0, 0) != CE_None) {
      throw InputError(path, "", "cannot read the image: " + last_gdal_error());
    }
    for (std::size_t i = 0; i < n; ++i)
      img.intensity[i] = iq[2 * i] * iq[2 * i] + iq[2 * i + 1] * iq[2 * i + 1];
    img.read_as = "complex |z|^2";
  } else {
    std::vector<double> v(n);
    if (GDALRasterIO(b, GF_Read, 0, 0, img.cols, img.rows, v.data(), img.cols, img.rows,
                     GDT_Float64, 0, 0) != CE_None) {
      throw InputError(path, "", "cannot read the image: " + last_gdal_error());
    }
    const bool is_float = type == GDT_Float32 || type == GDT_Float64;
    const PixelScale s = scale != PixelScale::automatic
                             ? scale
                             : (is_float ? PixelScale::power : PixelScale::amplitude);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (std::size_t i = 0; i < n; ++i) {
      const double x = v[i];
      if (!std::isfinite(x) || (has_nodata && x == nodata)) {
        img.intensity[i] = nan;
        continue;
      }
      const double p = s == PixelScale::power       ? x
                       : s == PixelScale::amplitude ? x * x
                                                    : std::pow(10.0, x / 10.0);
      img.intensity[i] = static_cast<float>(p);
    }
    img.read_as = s == PixelScale::power       ? "power"
                  : s == PixelScale::amplitude ? "amplitude^2"
                                               : "10^(dB/10)";
  }
}

}  // namespace

PixelScale parse_pixel_scale(const std::string& text, const std::string& option) {
  if (text == "auto") return PixelScale::automatic;
  if (text == "power") return PixelScale::power;
  if (text == "amplitude") return PixelScale::amplitude;
  if (text == "db") return PixelScale::db;
  throw InputError("", option,
                   fmt::format("expected auto, power, amplitude or db, got '{}'", text));
}

IntensityImage read_intensity_image(const std::string& path, int band, PixelScale scale) {
  ensure_gdal_registered();
  IntensityImage img;
  const bool product = ends_with(path, ".h5") || ends_with(path, ".hdf5");
  if (product) require_regular_input(path);
  img.source = product ? product_layer(path, band) : path;
  const int band_index = product ? 1 : band;
  // A product's layer is a GDAL subdataset name, not a path.
  const bool subdataset = product || img.source.rfind("HDF5:", 0) == 0;
  const GdalDataset ds =
      subdataset ? GdalDataset(GDALOpenEx(img.source.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY,
                                          nullptr, nullptr, nullptr))
                 : open_raster(img.source);
  if (!ds) throw InputError(path, "", "GDAL cannot open " + img.source + ": " + last_gdal_error());
  const int n_bands = GDALGetRasterCount(handle(ds));
  if (band_index < 1 || band_index > n_bands) {
    throw InputError(path, "band",
                     fmt::format("band {} asked for, the raster has {}", band_index, n_bands));
  }
  GDALRasterBandH b = GDALGetRasterBand(handle(ds), band_index);
  img.cols = GDALGetRasterXSize(handle(ds));
  img.rows = GDALGetRasterYSize(handle(ds));
  fill_intensity(b, scale, path, img);
  double gt[6];
  if (GDALGetGeoTransform(handle(ds), gt) == CE_None) {
    img.has_geotransform = true;
    for (int k = 0; k < 6; ++k) img.georef.geotransform[static_cast<std::size_t>(k)] = gt[k];
    const char* wkt = GDALGetProjectionRef(handle(ds));
    img.georef.crs_wkt = wkt != nullptr ? wkt : "";
  } else if (GDALGetGCPCount(handle(ds)) > 0) {
    // A raster on the radar's own grid placed by ground control points
    // (ris's slant-range products): kept, so that what is made of the image
    // can carry them too.
    const GDAL_GCP* gcps = GDALGetGCPs(handle(ds));
    for (int k = 0; k < GDALGetGCPCount(handle(ds)); ++k)
      img.georef.gcps.push_back(
          {gcps[k].dfGCPPixel, gcps[k].dfGCPLine, gcps[k].dfGCPX, gcps[k].dfGCPY, gcps[k].dfGCPZ});
    const char* wkt = GDALGetGCPProjection(handle(ds));
    img.georef.crs_wkt = wkt != nullptr ? wkt : "";
  }
  char** md = GDALGetMetadata(handle(ds), nullptr);
  for (int i = 0; md != nullptr && md[i] != nullptr; ++i) {
    const std::string item = md[i];
    const auto eq = item.find('=');
    if (eq != std::string::npos) img.metadata[item.substr(0, eq)] = item.substr(eq + 1);
  }
  return img;
}

}  // namespace ris

namespace ris {

IntensityImage read_intensity_image_on_grid(const std::string& path, int band, PixelScale scale,
                                            const IntensityImage& grid) {
  ensure_gdal_registered();
  const GdalDataset ds = open_raster(path);
  double gt[6];
  const char* wkt = GDALGetProjectionRef(handle(ds));
  const std::array<double, 6>& g = grid.georef.geotransform;
  if (!grid.has_geotransform || grid.georef.crs_wkt.empty() ||
      GDALGetGeoTransform(handle(ds), gt) != CE_None || wkt == nullptr || *wkt == 0) {
    throw InputError(path, "grid",
                     "the images differ in size and are not both georeferenced (a geotransform "
                     "and a CRS each): nothing says which pixels correspond");
  }
  if (g[2] != 0.0 || g[4] != 0.0 || !(g[5] < 0.0)) {
    throw InputError(path, "grid", "the first image's grid is rotated: resample it north-up first");
  }
  if (band != 1) {
    throw InputError(path, "band",
                     "a raster resampled onto the other image's grid is read from band 1");
  }
  WarpGrid w;
  w.crs_wkt = grid.georef.crs_wkt;
  w.min_x = g[0];
  w.max_y = g[3];
  w.cell_x = g[1];
  w.cell_y = -g[5];
  w.cols = grid.cols;
  w.rows = grid.rows;
  const GdalDataset warped = warp_band1(handle(ds), wkt, w, "bilinear", "Float64", "nan", path);
  IntensityImage img;
  img.source = path + " (resampled bilinearly onto the first image's grid)";
  img.cols = grid.cols;
  img.rows = grid.rows;
  fill_intensity(GDALGetRasterBand(handle(warped), 1), scale, path, img);
  img.georef = grid.georef;
  img.has_geotransform = true;
  return img;
}

}  // namespace ris
