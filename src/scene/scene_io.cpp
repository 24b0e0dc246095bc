#include "ris/scene/scene_io.h"

#include <fmt/format.h>
#include <gdal.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ris/io/gdal_util.h"
#include "ris/io/raster_io.h"
#include "ris/scene/dem_import.h"
#include "ris/scene/scene_stream.h"
#include "ris/util/error.h"

namespace ris {

SceneGeoTiffWriter::SceneGeoTiffWriter(const std::filesystem::path& path, const Scene& grid,
                                       const RasterMetadata& extra_metadata,
                                       const GeoTiffCompression& compression)
    : cols_(grid.cols) {
  const Georef georef{grid.geotransform(), grid.crs_wkt};
  RasterMetadata metadata = extra_metadata;
  metadata["RIS_SCENE"] = "1";
  writer_ = std::make_unique<GeoTiffBlockWriter<float>>(
      path, grid.cols, grid.rows, std::vector<std::string>{"elevation_m", "category"}, &georef,
      static_cast<double>(std::numeric_limits<float>::quiet_NaN()), metadata, compression);
}

SceneGeoTiffWriter::~SceneGeoTiffWriter() = default;

void SceneGeoTiffWriter::write_rows(const float* elevation_m, const std::uint16_t* category,
                                    const std::uint8_t* valid, int count) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::size_t n = static_cast<std::size_t>(count) * static_cast<std::size_t>(cols_);
  elevation_.resize(n);
  category_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const bool ok = valid[i] != 0;
    elevation_[i] = ok ? elevation_m[i] : nan;
    category_[i] = ok ? static_cast<float>(category[i]) : nan;
  }
  writer_->write({elevation_.data(), category_.data()}, count);
}

void SceneGeoTiffWriter::close() {
  writer_->close();
}

void write_scene_geotiff(const Scene& scene, const std::filesystem::path& path,
                         const RasterMetadata& extra_metadata) {
  scene.validate(path.string());
  SceneGeoTiffWriter out(path, scene, extra_metadata);
  constexpr int kBlockRows = 256;
  for (int r0 = 0; r0 < scene.rows; r0 += kBlockRows) {
    const int n = std::min(kBlockRows, scene.rows - r0);
    const std::size_t at = scene.index(r0, 0);
    out.write_rows(scene.elevation_m.data() + at, scene.category.data() + at,
                   scene.valid.data() + at, n);
  }
  out.close();
}

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
  const SceneStreamReader in(path, category_path);
  Scene scene = in.grid();
  check_scene_fits_in_memory(scene.rows, scene.cols, p, "");
  scene.elevation_m.resize(scene.size());
  scene.category.resize(scene.size());
  scene.valid.resize(scene.size());
  // In blocks of rows, so no whole-raster float copy is held besides the scene.
  const int block = std::max(1, std::max(in.block_rows(), 256));
  for (int r0 = 0; r0 < scene.rows; r0 += block) {
    const int n = std::min(block, scene.rows - r0);
    const std::size_t at = scene.index(r0, 0);
    in.read(r0, n, 0, scene.cols, scene.elevation_m.data() + at, scene.category.data() + at,
            scene.valid.data() + at);
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
