#include "ris/scene/scene_stream.h"

#include <cpl_conv.h>
#include <fmt/format.h>
#include <gdal.h>

#include <array>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include "ris/io/gdal_util.h"
#include "ris/scene/dem_import.h"
#include "ris/util/error.h"

namespace ris {

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

bool is_ris_scene(GDALDatasetH ds) {
  const char* flag = GDALGetMetadataItem(ds, "RIS_SCENE", nullptr);
  return flag != nullptr && std::string(flag) == "1" && GDALGetRasterCount(ds) >= 2;
}

// A band read as float over a window, with no-data and non-finite values as
// NaN.
void read_band_nan(GDALRasterBandH band, int row0, int rows, int col0, int cols, float* out,
                   const std::string& path, int b) {
  if (GDALRasterIO(band, GF_Read, col0, row0, cols, rows, out, cols, rows, GDT_Float32, 0, 0) !=
      CE_None) {
    throw InputError(path, "", fmt::format("cannot read band {}: {}", b, last_gdal_error()));
  }
  int has_nodata = 0;
  const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
  const float nodata_f = static_cast<float>(nodata);
  const bool check_nodata = has_nodata && !std::isnan(nodata);
  const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  for (std::size_t i = 0; i < n; ++i) {
    const float v = out[i];
    if (!std::isfinite(v) || (check_nodata && v == nodata_f))
      out[i] = std::numeric_limits<float>::quiet_NaN();
  }
}

}  // namespace

struct SceneStreamReader::Impl {
  GdalDataset ds;
  GdalDataset category_ds;  // a separate category raster, if any
  GDALRasterBandH elevation = nullptr;
  GDALRasterBandH category = nullptr;  // null: every cell kDefaultCategory
  std::string category_path;           // the file the categories come from
  int category_band = 1;
  mutable std::vector<float> scratch;
};

SceneStreamReader::SceneStreamReader(const std::filesystem::path& path,
                                     const std::optional<std::filesystem::path>& category_path)
    : impl_(std::make_unique<Impl>()), path_(path.string()) {
  const std::string& p = path_;
  if (dem_needs_import(path)) {
    throw InputError(p, "",
                     "a DEM in a geographic CRS (or in feet) is imported (reprojected) when read "
                     "whole, which a streamed run cannot do; import it once with: ris scene "
                     "import " +
                         p + " -o scene.tif");
  }
  // GDAL (3.6+) decodes the tiles a RasterIO request spans on all cores.
  CPLSetThreadLocalConfigOption("GDAL_NUM_THREADS", "ALL_CPUS");
  try {
    impl_->ds = open_raster(p);
  } catch (...) {
    CPLSetThreadLocalConfigOption("GDAL_NUM_THREADS", nullptr);
    throw;
  }
  CPLSetThreadLocalConfigOption("GDAL_NUM_THREADS", nullptr);
  GDALDatasetH ds = handle(impl_->ds);
  const Grid g = grid_of(ds);
  if (g.has_gt && (g.gt[2] != 0.0 || g.gt[4] != 0.0)) {
    throw InputError(p, "",
                     "rotated or sheared geotransforms are not supported; warp the raster "
                     "to a north-up grid first (gdalwarp)");
  }
  Scene& scene = grid_;
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
  const char* wkt = GDALGetProjectionRef(ds);
  if (wkt != nullptr) scene.crs_wkt = wkt;
  impl_->elevation = GDALGetRasterBand(ds, 1);
  GDALGetBlockSize(impl_->elevation, &block_cols_, &block_rows_);

  if (is_ris_scene(ds)) {
    if (category_path) {
      throw InputError(category_path->string(), "",
                       "the scene file " + p + " already holds categories (band 2)");
    }
    impl_->category = GDALGetRasterBand(ds, 2);
    impl_->category_path = p;
    impl_->category_band = 2;
  } else if (category_path) {
    const std::string cp = category_path->string();
    impl_->category_ds = open_raster(cp);
    const Grid cg = grid_of(handle(impl_->category_ds));
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
    impl_->category = GDALGetRasterBand(handle(impl_->category_ds), 1);
    impl_->category_path = cp;
  }
}

SceneStreamReader::~SceneStreamReader() = default;

bool SceneStreamReader::has_categories() const {
  return impl_->category != nullptr;
}

void SceneStreamReader::read(int row0, int rows, int col0, int cols, float* elevation_m,
                             std::uint16_t* category, std::uint8_t* valid) const {
  RIS_CHECK(row0 >= 0 && rows >= 0 && row0 + rows <= grid_.rows);
  RIS_CHECK(col0 >= 0 && cols >= 0 && col0 + cols <= grid_.cols);
  if (rows == 0 || cols == 0) return;
  const std::size_t n = static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  read_band_nan(impl_->elevation, row0, rows, col0, cols, elevation_m, path_, 1);
  for (std::size_t i = 0; i < n; ++i) {
    const bool ok = !std::isnan(elevation_m[i]);
    valid[i] = ok ? 1 : 0;
    if (!ok) elevation_m[i] = 0.0f;
    category[i] = kDefaultCategory;
  }
  if (impl_->category != nullptr) {
    std::vector<float>& cat = impl_->scratch;
    cat.resize(n);
    read_band_nan(impl_->category, row0, rows, col0, cols, cat.data(), impl_->category_path,
                  impl_->category_band);
    for (std::size_t i = 0; i < n; ++i) {
      const float c = cat[i];
      if (std::isnan(c)) {
        valid[i] = 0;
        continue;
      }
      if (c < 0.0f || c > static_cast<float>(kMaxCategory) || c != std::floor(c)) {
        const std::size_t w = static_cast<std::size_t>(cols);
        throw InputError(impl_->category_path, "category",
                         fmt::format("category value {} at column {}, row {} is not an integer in "
                                     "0..{}",
                                     c, col0 + static_cast<int>(i % w),
                                     row0 + static_cast<int>(i / w), kMaxCategory));
      }
      category[i] = static_cast<std::uint16_t>(c);
    }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (valid[i] == 0) category[i] = kNoDataCategory;
}

std::int64_t bound_gdal_cache(std::int64_t max_bytes) {
  ensure_gdal_registered();
  if (std::getenv("GDAL_CACHEMAX") == nullptr && GDALGetCacheMax64() > max_bytes)
    GDALSetCacheMax64(max_bytes);
  return GDALGetCacheMax64();
}

}  // namespace ris
