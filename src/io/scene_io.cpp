#include "ris/io/scene_io.h"

#include <fmt/format.h>
#include <gdal.h>
#include <spdlog/spdlog.h>

#include <cmath>
#include <limits>
#include <vector>

#include "ris/io/dem_import.h"
#include "ris/io/gdal_util.h"
#include "ris/io/raster_io.h"
#include "ris/util/error.h"

namespace ris {

void write_scene_geotiff(const Scene& scene, const std::filesystem::path& path,
                         const RasterMetadata& extra_metadata) {
  scene.validate(path.string());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<float> elevation(scene.size());
  std::vector<float> category(scene.size());
  for (size_t i = 0; i < scene.size(); ++i) {
    const bool ok = scene.valid[i] != 0;
    elevation[i] = ok ? scene.elevation_m[i] : nan;
    category[i] = ok ? static_cast<float>(scene.category[i]) : nan;
  }
  Georef georef{scene.geotransform(), scene.crs_wkt};
  RasterMetadata metadata = extra_metadata;
  metadata["RIS_SCENE"] = "1";
  write_geotiff_bands<float>(path,
                             {{elevation.data(), "elevation_m"}, {category.data(), "category"}},
                             scene.cols, scene.rows, &georef, static_cast<double>(nan), metadata);
}

namespace {

struct Grid {
  int cols = 0;
  int rows = 0;
  std::array<double, 6> gt{0, 1, 0, 0, 0, -1};
  bool has_gt = false;
};

Grid grid_of(GDALDatasetH ds) {
  Grid g;
  g.cols = GDALGetRasterXSize(ds);
  g.rows = GDALGetRasterYSize(ds);
  g.has_gt = GDALGetGeoTransform(ds, g.gt.data()) == CE_None;
  return g;
}

// Reads band `b` as float, with no-data and non-finite values as NaN.
std::vector<float> read_band_nan(GDALDatasetH ds, int b, const std::string& path) {
  GDALRasterBandH band = GDALGetRasterBand(ds, b);
  const int cols = GDALGetRasterXSize(ds);
  const int rows = GDALGetRasterYSize(ds);
  std::vector<float> data(static_cast<size_t>(cols) * rows);
  if (GDALRasterIO(band, GF_Read, 0, 0, cols, rows, data.data(), cols, rows, GDT_Float32, 0, 0) !=
      CE_None) {
    throw InputError(path, "", fmt::format("cannot read band {}: {}", b, last_gdal_error()));
  }
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  const float nodata_f = static_cast<float>(nodata);
  for (float& v : data) {
    if (!std::isfinite(v) || (has_nodata && !std::isnan(nodata) && v == nodata_f)) {
      v = std::numeric_limits<float>::quiet_NaN();
    }
  }
  return data;
}

bool is_ris_scene(GDALDatasetH ds) {
  const char* flag = GDALGetMetadataItem(ds, "RIS_SCENE", nullptr);
  return flag != nullptr && std::string(flag) == "1" && GDALGetRasterCount(ds) >= 2;
}

void fill_categories(Scene& scene, const std::vector<float>& cat, const std::string& path) {
  for (size_t i = 0; i < scene.size(); ++i) {
    const float c = cat[i];
    if (std::isnan(c)) {
      scene.valid[i] = 0;
      scene.category[i] = kNoDataCategory;
      continue;
    }
    if (c < 0.0f || c > static_cast<float>(kMaxCategory) || c != std::floor(c)) {
      throw InputError(path, "category",
                       fmt::format("category value {} at column {}, row {} is not an integer in "
                                   "0..{}",
                                   c, i % scene.cols, i / scene.cols, kMaxCategory));
    }
    scene.category[i] = static_cast<std::uint16_t>(c);
  }
}

}  // namespace

Scene read_scene(const std::filesystem::path& path,
                 const std::optional<std::filesystem::path>& category_path) {
  const std::string p = path.string();
  if (dem_needs_import(path)) {
    // A geographic DEM: import on the fly (UTM zone of its centre, default cell size).
    if (category_path) {
      throw InputError(category_path->string(), "",
                       "a category raster cannot be combined with the geographic DEM " + p +
                           "; import it with: ris scene import " + p +
                           " --landcover LC --mapping M -o scene.tif");
    }
    ImportedDem dem = import_dem(path);
    spdlog::info("{}: imported into {} at {} m cells ({} no-data cells)", p, dem.frame,
                 dem.scene.dx_m, dem.nodata_cells);
    return std::move(dem.scene);
  }
  GdalDataset ds = open_raster(p);
  const Grid g = grid_of(handle(ds));
  check_scene_fits_in_memory(g.rows, g.cols, p, "");
  if (g.has_gt && (g.gt[2] != 0.0 || g.gt[4] != 0.0)) {
    throw InputError(p, "",
                     "rotated or sheared geotransforms are not supported; warp the raster "
                     "to a north-up grid first (gdalwarp)");
  }

  Scene scene;
  scene.rows = g.rows;
  scene.cols = g.cols;
  if (g.has_gt) {
    scene.origin_x_m = g.gt[0];
    scene.dx_m = g.gt[1];
    scene.origin_y_m = g.gt[3];
    scene.dy_m = -g.gt[5];
    if (!(scene.dx_m > 0.0) || !(scene.dy_m > 0.0)) {
      throw InputError(p, "",
                       fmt::format("expected a north-up raster (positive pixel width, "
                                   "negative pixel height), got {} x {}",
                                   g.gt[1], g.gt[5]));
    }
  } else {
    // No georeferencing: one unit per cell, origin so that the south-west
    // corner is (0, 0). Callers that need metres must supply the cell size.
    scene.dx_m = scene.dy_m = 1.0;
    scene.origin_y_m = g.rows;
  }
  const char* wkt = GDALGetProjectionRef(handle(ds));
  if (wkt != nullptr) scene.crs_wkt = wkt;

  std::vector<float> elevation = read_band_nan(handle(ds), 1, p);
  scene.elevation_m.resize(scene.size());
  scene.valid.assign(scene.size(), 1);
  scene.category.assign(scene.size(), 0);
  for (size_t i = 0; i < scene.size(); ++i) {
    if (std::isnan(elevation[i])) {
      scene.valid[i] = 0;
      scene.elevation_m[i] = 0.0f;
    } else {
      scene.elevation_m[i] = elevation[i];
    }
  }

  if (is_ris_scene(handle(ds))) {
    if (category_path) {
      throw InputError(category_path->string(), "",
                       "the scene file " + p + " already holds categories (band 2)");
    }
    fill_categories(scene, read_band_nan(handle(ds), 2, p), p);
  } else if (category_path) {
    const std::string cp = category_path->string();
    GdalDataset cds = open_raster(cp);
    const Grid cg = grid_of(handle(cds));
    bool same = cg.cols == g.cols && cg.rows == g.rows && cg.has_gt == g.has_gt;
    for (int k = 0; same && g.has_gt && k < 6; ++k) {
      same = std::abs(cg.gt[k] - g.gt[k]) <= 1e-9 * std::max(1.0, std::abs(g.gt[k]));
    }
    if (!same) {
      throw InputError(cp, "",
                       fmt::format("the category raster ({} x {}) is not on the elevation "
                                   "grid of {} ({} x {}, same geotransform required)",
                                   cg.cols, cg.rows, p, g.cols, g.rows));
    }
    fill_categories(scene, read_band_nan(handle(cds), 1, cp), cp);
  }
  for (size_t i = 0; i < scene.size(); ++i) {
    if (scene.valid[i] == 0) scene.category[i] = kNoDataCategory;
  }
  scene.validate(p);
  return scene;
}

std::size_t count_nodata(const Scene& scene) {
  std::size_t n = 0;
  for (auto v : scene.valid) n += (v == 0);
  return n;
}

}  // namespace ris
