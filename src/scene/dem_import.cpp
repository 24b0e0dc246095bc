#include "ris/scene/dem_import.h"

#include <cpl_string.h>
#include <fmt/format.h>
#include <gdal.h>
#include <gdal_alg.h>
#include <ogr_spatialref.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "ris/io/gdal_util.h"
#include "ris/util/error.h"

namespace ris {

namespace {

std::string srs_name(const OGRSpatialReference& srs) {
  const char* name = srs.GetName();
  std::string out = (name != nullptr && *name != '\0') ? name : "unnamed CRS";
  const char* auth = srs.GetAuthorityName(nullptr);
  const char* code = srs.GetAuthorityCode(nullptr);
  if (auth != nullptr && code != nullptr) out += fmt::format(" ({}:{})", auth, code);
  return out;
}

// The DEM's CRS: the user's override, else the file's; refuses a DEM without.
OGRSpatialReference source_crs(GDALDatasetH ds, const std::string& path,
                               const DemImportOptions& options) {
  OGRSpatialReference srs;
  if (options.crs) {
    if (srs.SetFromUserInput(options.crs->c_str()) != OGRERR_NONE) {
      throw InputError("", options.crs_key,
                       fmt::format("cannot read the CRS \"{}\" (expected e.g. EPSG:4326, "
                                   "EPSG:32633, a WKT or a PROJ string)",
                                   *options.crs));
    }
    if (const OGRSpatialReferenceH own = GDALGetSpatialRef(ds); own != nullptr) {
      spdlog::warn("{}: overriding the file's CRS ({}) with {}", path,
                   srs_name(*OGRSpatialReference::FromHandle(own)), srs_name(srs));
    }
    return srs;
  }
  const OGRSpatialReferenceH own = GDALGetSpatialRef(ds);
  if (own == nullptr || OGRSpatialReference::FromHandle(own)->IsEmpty()) {
    throw InputError(path, "crs",
                     fmt::format("the DEM has no CRS, so ris cannot tell where it is or what "
                                 "its units are; give it with {} (e.g. {} EPSG:4326 for "
                                 "latitude/longitude in degrees on WGS 84)",
                                 options.crs_key, options.crs_key));
  }
  srs = *OGRSpatialReference::FromHandle(own);
  return srs;
}

// What the heights are relative to: the DEM's declared vertical CRS, or the
// convention of its format.
std::string vertical_datum_of(const OGRSpatialReference& srs, GDALDatasetH ds) {
  const char* vert = srs.GetAttrValue("COMPD_CS|VERT_CS");
  if (vert == nullptr) vert = srs.GetAttrValue("VERT_CS");
  if (vert != nullptr) return fmt::format("{} (declared by the DEM)", vert);
  const char* driver = GDALGetDriverShortName(GDALGetDatasetDriver(ds));
  if (driver != nullptr && std::string(driver) == "SRTMHGT") {
    return "EGM96 geoid heights (SRTM .hgt convention)";
  }
  return "heights as given by the DEM (no vertical datum declared; SRTM-derived DEMs "
         "give EGM96 geoid heights, Copernicus DEM EGM2008)";
}

// Metres per unit of the band's values (GDALGetRasterUnitType).
double height_unit_m(GDALRasterBandH band, const std::string& path) {
  std::string unit = GDALGetRasterUnitType(band);
  std::transform(unit.begin(), unit.end(), unit.begin(),
                 [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
  if (unit.empty() || unit == "m" || unit == "metre" || unit == "meter" || unit == "metres" ||
      unit == "meters") {
    return 1.0;
  }
  if (unit == "ft" || unit == "foot" || unit == "feet") return 0.3048;
  if (unit == "us survey foot" || unit == "ftus" || unit == "us-ft") return 1200.0 / 3937.0;
  throw InputError(path, "unit",
                   fmt::format("unknown height unit \"{}\" (expected metres or feet)", unit));
}

// Band 1 as float with no-data and non-finite values as NaN.
std::vector<float> read_heights(GDALDatasetH ds, int cols, int rows, const std::string& path) {
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  std::vector<float> data(static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows));
  if (GDALRasterIO(band, GF_Read, 0, 0, cols, rows, data.data(), cols, rows, GDT_Float32, 0, 0) !=
      CE_None) {
    throw InputError(path, "", "cannot read the elevation band: " + last_gdal_error());
  }
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  const float nodata_f = static_cast<float>(nodata);
  const bool check = has_nodata != 0 && !std::isnan(nodata);
  for (float& v : data) {
    if (!std::isfinite(v) || (check && v == nodata_f)) v = std::numeric_limits<float>::quiet_NaN();
  }
  return data;
}

struct TargetGrid {
  double min_x = 0.0, max_y = 0.0;  // north-west corner
  double cell_m = 0.0;
  int cols = 0, rows = 0;
};

// The output grid of a warp: the cell size is the user's, or gdalwarp's
// suggestion (square cells keeping the diagonal's cell count) rounded to two
// significant digits; the extent is the DEM's outline transformed by PROJ
// (densified edges), snapped outwards to multiples of the cell size.
TargetGrid plan_warp(GDALDatasetH src, const std::array<double, 6>& src_gt,
                     const OGRSpatialReference& src_srs, const OGRSpatialReference& target_srs,
                     const std::string& path, const DemImportOptions& options) {
  double cell_m = 0.0;
  if (options.cell_size_m) {
    cell_m = *options.cell_size_m;
  } else {
    const std::string src_opt = "SRC_SRS=" + wkt_of(src_srs);
    const std::string dst_opt = "DST_SRS=" + wkt_of(target_srs);
    const char* const topts[] = {src_opt.c_str(), dst_opt.c_str(), nullptr};
    void* transformer = GDALCreateGenImgProjTransformer2(src, nullptr, const_cast<char**>(topts));
    if (transformer == nullptr) {
      throw InputError(path, "crs", "PROJ cannot transform the DEM's CRS: " + last_gdal_error());
    }
    std::array<double, 6> gt{};
    int px = 0, lines = 0;
    const CPLErr err =
        GDALSuggestedWarpOutput(src, GDALGenImgProjTransform, transformer, gt.data(), &px, &lines);
    GDALDestroyGenImgProjTransformer(transformer);
    if (err != CE_None) {
      throw InputError(path, "", "cannot compute the reprojected cell size: " + last_gdal_error());
    }
    // A hostile or broken geotransform (zero, infinite or NaN pixel size)
    // gets here as a suggestion GDAL computed from it.
    if (!(std::isfinite(gt[1]) && gt[1] > 0.0)) {
      throw InputError(path, "",
                       fmt::format("the DEM's georeferencing gives no usable cell size (GDAL "
                                   "suggests {:g} m); check its geotransform",
                                   gt[1]));
    }
    cell_m = round_two_significant(gt[1]);
  }
  // Outline of the DEM in its own CRS (all four corners, for rotated grids).
  const int cols = GDALGetRasterXSize(src), rows = GDALGetRasterYSize(src);
  const auto [sx0, sy0, sx1, sy1] = raster_outline(src_gt, cols, rows);
  std::unique_ptr<OGRCoordinateTransformation> ct(
      OGRCreateCoordinateTransformation(&src_srs, &target_srs));
  std::array<double, 4> e{};
  if (!ct || !ct->TransformBounds(sx0, sy0, sx1, sy1, &e[0], &e[1], &e[2], &e[3], 101)) {
    throw InputError(path, "crs", "PROJ cannot transform the DEM's outline: " + last_gdal_error());
  }
  TargetGrid g;
  g.cell_m = cell_m;
  const double min_x = std::floor(e[0] / cell_m) * cell_m;
  const double min_y = std::floor(e[1] / cell_m) * cell_m;
  const double max_x = std::ceil(e[2] / cell_m) * cell_m;
  const double max_y = std::ceil(e[3] / cell_m) * cell_m;
  const double n_cols = std::round((max_x - min_x) / cell_m);
  const double n_rows = std::round((max_y - min_y) / cell_m);
  // Checked as doubles first: converting an infinite or huge count to an
  // integer is undefined.
  constexpr double kMaxSide = 2147483647.0;
  if (!(n_cols >= 1.0 && n_rows >= 1.0 && n_cols <= kMaxSide && n_rows <= kMaxSide)) {
    throw InputError(path, options.cell_size_key,
                     fmt::format("the reprojected DEM would be {:g} x {:g} cells of {:g} m: its "
                                 "outline or cell size is not usable",
                                 n_rows, n_cols, cell_m));
  }
  check_scene_fits_in_memory(static_cast<std::int64_t>(n_rows), static_cast<std::int64_t>(n_cols),
                             path, options.cell_size_key);
  g.min_x = min_x;
  g.max_y = max_y;
  g.cols = static_cast<int>(n_cols);
  g.rows = static_cast<int>(n_rows);
  return g;
}

// The UTM zone of the DEM's centre on the DEM's geodetic datum (a DEM not
// in metres is warped into it); frame_note says so.
OGRSpatialReference utm_frame_of_centre(const OGRSpatialReference& horizontal,
                                        const std::array<double, 6>& src_gt, int src_cols,
                                        int src_rows, const std::string& path,
                                        std::string& frame_note) {
  if (horizontal.IsLocal()) {
    throw InputError(path, "crs", "a local CRS not in metres cannot be converted to metres");
  }
  OGRSpatialReference geog;
  geog.CopyGeogCSFrom(&horizontal);
  geog.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  double cx = src_gt[0] + 0.5 * src_cols * src_gt[1] + 0.5 * src_rows * src_gt[2];
  double cy = src_gt[3] + 0.5 * src_cols * src_gt[4] + 0.5 * src_rows * src_gt[5];
  std::unique_ptr<OGRCoordinateTransformation> to_geog(
      OGRCreateCoordinateTransformation(&horizontal, &geog));
  if (!to_geog || !to_geog->Transform(1, &cx, &cy)) {
    throw InputError(path, "crs", "cannot find the DEM centre's latitude/longitude");
  }
  const int zone = utm_zone_of_longitude(cx);
  const bool north = cy >= 0.0;
  OGRSpatialReference target;
  target.CopyGeogCSFrom(&horizontal);
  target.SetUTM(zone, north ? TRUE : FALSE);
  target.SetProjCS(
      fmt::format("{} / UTM zone {}{}", geog.GetName(), zone, north ? "N" : "S").c_str());
  target.AutoIdentifyEPSG();
  frame_note = fmt::format(
      "UTM zone {}{} of the DEM centre ({:.5f} deg {}, {:.5f} deg {}), reprojected with "
      "GDAL's warper (bilinear heights; no-data from the nearest posting)",
      zone, north ? "N" : "S", std::abs(cy), cy >= 0 ? "N" : "S", std::abs(cx),
      cx >= 0 ? "E" : "W");
  return target;
}

// The scene's heights in metres (heights x scale x unit + offset x unit);
// no-data (NaN) cells masked and counted in out.nodata_cells.
void fill_scene_heights(const std::vector<float>& heights, double scale, double offset,
                        double unit_m, std::uint16_t category, const std::string& path,
                        ImportedDem& out) {
  Scene& scene = out.scene;
  scene.elevation_m.resize(scene.size());
  scene.category.assign(scene.size(), category);
  scene.valid.assign(scene.size(), 1);
  const double factor_m = scale * unit_m;
  const double offset_m = offset * unit_m;
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (std::isnan(heights[i])) {
      scene.valid[i] = 0;
      scene.elevation_m[i] = 0.0f;
      scene.category[i] = kNoDataCategory;
      ++out.nodata_cells;
    } else {
      scene.elevation_m[i] = static_cast<float>(heights[i] * factor_m + offset_m);
    }
  }
  scene.validate(path);
  if (out.nodata_cells == scene.size()) {
    throw InputError(path, "", "the DEM holds no valid heights (every cell is no-data)");
  }
}

}  // namespace

int utm_zone_of_longitude(double lon_deg) {
  // Same rule as utm_wkt_for (ris/scene/geo_frame.h).
  double lon = std::fmod(lon_deg + 180.0, 360.0);
  if (lon < 0.0) lon += 360.0;
  return std::clamp(static_cast<int>(std::floor(lon / 6.0)) + 1, 1, 60);
}

double round_two_significant(double value) {
  RIS_CHECK(value > 0.0 && std::isfinite(value));
  const double scale = std::pow(10.0, std::floor(std::log10(value)) - 1.0);
  return std::round(value / scale) * scale;
}

bool dem_needs_import(const std::filesystem::path& dem_path) {
  GdalDataset ds = open_raster(dem_path.string());
  const char* flag = GDALGetMetadataItem(handle(ds), "RIS_SCENE", nullptr);
  if (flag != nullptr && std::string(flag) == "1") return false;
  const OGRSpatialReferenceH h = GDALGetSpatialRef(handle(ds));
  if (h == nullptr) return false;
  const OGRSpatialReference* srs = OGRSpatialReference::FromHandle(h);
  if (srs->IsEmpty()) return false;
  if (srs->IsGeographic()) return true;
  return srs->IsProjected() && std::abs(srs->GetLinearUnits() - 1.0) > 1e-12;
}

ImportedDem import_dem(const std::filesystem::path& dem_path, const DemImportOptions& options) {
  const std::string path = dem_path.string();
  if (options.cell_size_m && !(*options.cell_size_m > 0.0 && std::isfinite(*options.cell_size_m))) {
    throw InputError("", options.cell_size_key,
                     fmt::format("expected a positive cell size, got {} m", *options.cell_size_m));
  }
  GdalDataset src = open_raster(path);
  GDALDatasetH ds = handle(src);
  const int src_cols = GDALGetRasterXSize(ds);
  const int src_rows = GDALGetRasterYSize(ds);
  std::array<double, 6> src_gt{};
  if (GDALGetGeoTransform(ds, src_gt.data()) != CE_None) {
    throw InputError(path, "geotransform",
                     "the DEM has no geotransform, so its cells cannot be placed on the ground "
                     "(georeference it first, e.g. gdal_translate -a_ullr ... -a_srs ...)");
  }
  OGRSpatialReference srs = source_crs(ds, path, options);
  srs.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  const std::string vertical = vertical_datum_of(srs, ds);
  OGRSpatialReference horizontal = srs;
  horizontal.StripVertical();
  if (!horizontal.IsGeographic() && !horizontal.IsProjected() && !horizontal.IsLocal()) {
    throw InputError(
        path, "crs",
        fmt::format("the DEM's CRS {} is neither geographic nor projected", srs_name(srs)));
  }
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  const double unit_m = height_unit_m(band, path);
  int has_scale = 0, has_offset = 0;
  double scale = GDALGetRasterScale(band, &has_scale);
  double offset = GDALGetRasterOffset(band, &has_offset);
  if (has_scale == 0) scale = 1.0;
  if (has_offset == 0) offset = 0.0;

  ImportedDem out;
  Scene& scene = out.scene;
  const bool metric = (horizontal.IsProjected() || horizontal.IsLocal()) &&
                      std::abs(horizontal.GetLinearUnits() - 1.0) <= 1e-12;
  const bool north_up = src_gt[2] == 0.0 && src_gt[4] == 0.0 && src_gt[1] > 0.0 && src_gt[5] < 0.0;
  const bool same_cells =
      !options.cell_size_m || (std::abs(*options.cell_size_m - src_gt[1]) <= 1e-9 * src_gt[1] &&
                               std::abs(*options.cell_size_m + src_gt[5]) <= 1e-9 * src_gt[1]);
  std::vector<float> heights;
  std::string frame_note;

  if (metric && north_up && same_cells) {
    // A metric north-up DEM is the scene grid as it stands.
    check_scene_fits_in_memory(src_rows, src_cols, path, options.cell_size_key);
    scene.rows = src_rows;
    scene.cols = src_cols;
    scene.origin_x_m = src_gt[0];
    scene.dx_m = src_gt[1];
    scene.origin_y_m = src_gt[3];
    scene.dy_m = -src_gt[5];
    scene.crs_wkt = wkt_of(horizontal);
    heights = read_heights(ds, src_cols, src_rows, path);
    out.frame = horizontal.GetName() != nullptr ? horizontal.GetName() : "local metric frame";
    frame_note = "the DEM's own CRS and grid (no resampling)";
  } else {
    // Geographic (or non-metric, rotated, resized): one warp into a metric
    // frame. The frame is the DEM's own projected CRS when it is metric,
    // else the UTM zone of the DEM's centre on the DEM's geodetic datum.
    OGRSpatialReference target;
    if (metric) {
      target = horizontal;
      frame_note = "the DEM's own CRS, resampled with GDAL's warper (bilinear)";
    } else {
      target = utm_frame_of_centre(horizontal, src_gt, src_cols, src_rows, path, frame_note);
    }
    target.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    // The horizontal CRS only: heights stay as the DEM gives them (no
    // automatic geoid-to-ellipsoid shift by the warper).
    const std::string src_wkt = wkt_of(horizontal);
    const std::string target_wkt = wkt_of(target);
    const TargetGrid g = plan_warp(ds, src_gt, horizontal, target, path, options);
    const WarpGrid grid{target_wkt, g.min_x, g.max_y, g.cell_m, g.cell_m, g.cols, g.rows};
    GdalDataset smooth = warp_band1(ds, src_wkt, grid, "bilinear", "Float32", "nan", path);
    GdalDataset nearest = warp_band1(ds, src_wkt, grid, "near", "Float32", "nan", path);
    heights = read_heights(handle(smooth), g.cols, g.rows, path);
    const std::vector<float> mask = read_heights(handle(nearest), g.cols, g.rows, path);
    // A cell is data only when the posting nearest its centre is data, so
    // bilinear interpolation neither fills holes nor grows the DEM's edge.
    for (std::size_t i = 0; i < heights.size(); ++i) {
      if (std::isnan(mask[i])) heights[i] = std::numeric_limits<float>::quiet_NaN();
    }
    scene.rows = g.rows;
    scene.cols = g.cols;
    scene.dx_m = scene.dy_m = g.cell_m;
    scene.origin_x_m = g.min_x;
    scene.origin_y_m = g.max_y;
    scene.crs_wkt = target_wkt;
    out.reprojected = true;
    out.frame = target.GetName() != nullptr ? target.GetName() : "UTM";
  }

  // Heights in metres; no-data cells masked and counted.
  fill_scene_heights(heights, scale, offset, unit_m, options.category, path, out);
  out.vertical_datum = vertical;
  out.metadata = {
      {"RIS_SOURCE_DEM", dem_path.filename().string()},
      {"RIS_SOURCE_CRS", srs_name(srs)},
      {"RIS_FRAME", fmt::format("{}: {}", out.frame, frame_note)},
      {"RIS_VERTICAL_DATUM", vertical},
      {"RIS_CELL_SIZE_M", fmt::format("{} x {}", scene.dx_m, scene.dy_m)},
      {"RIS_NODATA_CELLS", std::to_string(out.nodata_cells)},
  };
  if (out.nodata_cells > 0) {
    spdlog::info("{}: {} of {} cells are no-data ({:.2f}%), masked", path, out.nodata_cells,
                 scene.size(), 100.0 * double(out.nodata_cells) / double(scene.size()));
  }
  return out;
}

}  // namespace ris
