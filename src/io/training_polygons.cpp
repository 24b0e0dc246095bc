#include "ris/io/training_polygons.h"

#include <fmt/format.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <ogr_api.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "ris/io/gdal_util.h"
#include "ris/io/safe_paths.h"
#include "ris/util/error.h"

namespace ris {

namespace {

GdalDataset open_vector(const std::string& path) {
  ensure_gdal_registered();
  require_regular_input(path, "--training");
  CPLErrorReset();
  GDALDatasetH ds =
      GDALOpenEx(path.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
  if (ds == nullptr) {
    throw InputError(
        path, "--training",
        "not a vector file GDAL reads (GeoJSON, GeoPackage, ...): " + last_gdal_error());
  }
  return GdalDataset(ds);
}

// Checks every feature's attribute (an integer 1..255) and returns the
// number of features and the layers' extent (in their own CRS).
std::size_t check_layer(OGRLayerH layer, const std::string& path, const std::string& attribute,
                        OGREnvelope& extent) {
  OGRFeatureDefnH defn = OGR_L_GetLayerDefn(layer);
  const int field = OGR_FD_GetFieldIndex(defn, attribute.c_str());
  if (field < 0) {
    throw InputError(path, attribute,
                     fmt::format("layer '{}' has no attribute '{}' (the category of each polygon, "
                                 "an integer 1..255)",
                                 OGR_L_GetName(layer), attribute));
  }
  std::size_t n = 0;
  OGR_L_ResetReading(layer);
  while (OGRFeatureH f = OGR_L_GetNextFeature(layer)) {
    const long long fid = OGR_F_GetFID(f);
    const bool set = OGR_F_IsFieldSetAndNotNull(f, field) != 0;
    const double v = set ? OGR_F_GetFieldAsDouble(f, field) : 0.0;
    const std::string text = set ? OGR_F_GetFieldAsString(f, field) : "(null)";
    OGRGeometryH g = OGR_F_GetGeometryRef(f);
    OGREnvelope e;
    if (g != nullptr) OGR_G_GetEnvelope(g, &e);
    OGR_F_Destroy(f);
    if (!set || v != std::floor(v) || v < 1 || v > 255) {
      throw InputError(path, attribute,
                       fmt::format("feature {} of layer '{}': expected an integer category 1..255, "
                                   "got '{}'",
                                   fid, OGR_L_GetName(layer), text));
    }
    if (g == nullptr) {
      throw InputError(
          path, attribute,
          fmt::format("feature {} of layer '{}' has no geometry", fid, OGR_L_GetName(layer)));
    }
    extent.Merge(e);
    ++n;
  }
  return n;
}

// The image's georeferencing on the in-memory grid: its geotransform, or
// its ground control points (GDAL's rasterizer then places the polygons by
// a polynomial fitted to them, as gdalwarp does).
void place_grid(GDALDatasetH ds, const Georef& georef) {
  if (georef.gcps.empty()) {
    std::array<double, 6> gt = georef.geotransform;
    GDALSetGeoTransform(ds, gt.data());
    if (!georef.crs_wkt.empty()) GDALSetProjection(ds, georef.crs_wkt.c_str());
    return;
  }
  std::vector<GDAL_GCP> gcps(georef.gcps.size());
  std::vector<std::string> ids(georef.gcps.size());
  for (std::size_t i = 0; i < gcps.size(); ++i) {
    const GroundControlPoint& g = georef.gcps[i];
    ids[i] = std::to_string(i + 1);
    gcps[i] = {ids[i].data(), const_cast<char*>(""), g.pixel, g.line, g.x, g.y, g.z};
  }
  GDALSetGCPs(ds, static_cast<int>(gcps.size()), gcps.data(), georef.crs_wkt.c_str());
}

// {x0, y0, x1, y1} of the image in its CRS: of its corners, or of its GCPs.
std::array<double, 4> image_bounds(const Georef& georef, int cols, int rows) {
  if (georef.gcps.empty()) return raster_outline(georef.geotransform, cols, rows);
  std::array<double, 4> b{1e300, 1e300, -1e300, -1e300};
  for (const GroundControlPoint& g : georef.gcps)
    b = {std::min(b[0], g.x), std::min(b[1], g.y), std::max(b[2], g.x), std::max(b[3], g.y)};
  return b;
}

}  // namespace

TrainingPixels rasterize_training_polygons(const std::string& path, const std::string& attribute,
                                           const Georef& georef, int cols, int rows) {
  const GdalDataset vec = open_vector(path);
  std::vector<OGRLayerH> layers;
  TrainingPixels out;
  OGREnvelope extent;
  for (int i = 0; i < GDALDatasetGetLayerCount(handle(vec)); ++i) {
    OGRLayerH layer = GDALDatasetGetLayer(handle(vec), i);
    out.features += check_layer(layer, path, attribute, extent);
    layers.push_back(layer);
  }
  if (out.features == 0) throw InputError(path, "--training", "no polygons in the file");

  ensure_gdal_writers_registered();
  GDALDriverH mem = GDALGetDriverByName("MEM");
  const GdalDataset grid(GDALCreate(mem, "", cols, rows, 1, GDT_Byte, nullptr));
  RIS_CHECK(grid != nullptr);
  place_grid(handle(grid), georef);
  int band = 1;
  const std::string burn = "ATTRIBUTE=" + attribute;
  char* options[] = {const_cast<char*>(burn.c_str()), nullptr};
  CPLErrorReset();
  if (GDALRasterizeLayers(handle(grid), 1, &band, static_cast<int>(layers.size()), layers.data(),
                          nullptr, nullptr, nullptr, options, nullptr, nullptr) != CE_None) {
    throw InputError(path, "--training", "GDAL cannot burn the polygons: " + last_gdal_error());
  }
  out.codes.resize(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows));
  if (GDALRasterIO(GDALGetRasterBand(handle(grid), 1), GF_Read, 0, 0, cols, rows, out.codes.data(),
                   cols, rows, GDT_Byte, 0, 0) != CE_None) {
    throw InputError(path, "--training", "GDAL cannot read the burnt polygons back");
  }
  for (const std::uint8_t c : out.codes)
    if (c != 0) ++out.pixels[c];
  if (out.pixels.empty()) {
    const std::array<double, 4> b = image_bounds(georef, cols, rows);
    throw InputError(
        path, "--training",
        fmt::format("none of its {} polygons covers a pixel of the image: the polygons span "
                    "x {:.6g}..{:.6g}, y {:.6g}..{:.6g} (their CRS); the image x {:.6g}..{:.6g}, "
                    "y {:.6g}..{:.6g}",
                    out.features, extent.MinX, extent.MaxX, extent.MinY, extent.MaxY, b[0], b[2],
                    b[1], b[3]));
  }
  return out;
}

}  // namespace ris
