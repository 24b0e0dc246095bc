#include "ris/scene/scene_io.h"

#include <cpl_error.h>
#include <fmt/format.h>
#include <gdal.h>
#include <gdal_utils.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <vector>

#include "ris/io/atomic_file.h"
#include "ris/io/gdal_util.h"
#include "ris/io/raster_io.h"
#include "ris/scene/dem_import.h"
#include "ris/scene/scene_stream.h"
#include "ris/util/error.h"

namespace ris {

namespace {

// The VRT form's parts, beside the VRT: <stem>_elevation.tif, <stem>_category.tif.
std::filesystem::path part_path(const std::filesystem::path& vrt, const char* part) {
  return vrt.parent_path() / (vrt.stem().string() + "_" + part + ".tif");
}

// The scene's metadata (RIS_SCENE=1 and the caller's items) on a dataset.
void set_metadata(GDALDatasetH ds, const RasterMetadata& metadata) {
  for (const auto& [k, v] : metadata) GDALSetMetadataItem(ds, k.c_str(), v.c_str(), nullptr);
}

// The VRT binding the two parts (already in place) as bands 1 and 2, with
// their types and no-data (gdalbuildvrt -separate), written to a temporary
// name in the VRT's folder, so the sources are recorded relative to it, and
// renamed into place.
void write_scene_vrt(const std::filesystem::path& vrt, const RasterMetadata& metadata) {
  ensure_gdal_registered();
  const std::string elevation = part_path(vrt, "elevation").string();
  const std::string category = part_path(vrt, "category").string();
  AtomicPath out(vrt);
  const char* args[] = {"-separate", "-q", nullptr};
  GDALBuildVRTOptions* options = GDALBuildVRTOptionsNew(const_cast<char**>(args), nullptr);
  const char* sources[] = {elevation.c_str(), category.c_str()};
  int usage_error = 0;
  GdalDataset ds(GDALBuildVRT(out.temp_path().c_str(), 2, nullptr, sources, options, &usage_error));
  GDALBuildVRTOptionsFree(options);
  if (ds == nullptr)
    throw InputError(vrt.string(), "", "cannot write the scene VRT: " + last_gdal_error());
  set_metadata(handle(ds), metadata);
  const char* descriptions[] = {"elevation_m", "category"};
  for (int b = 0; b < 2; ++b)
    GDALSetDescription(GDALGetRasterBand(handle(ds), b + 1), descriptions[b]);
  GDALSetRasterUnitType(GDALGetRasterBand(handle(ds), 1), "m");
  CPLErrorReset();
  GDALClose(ds.release());
  if (CPLGetLastErrorType() == CE_Failure || CPLGetLastErrorType() == CE_Fatal)
    throw InputError(vrt.string(), "", "cannot write the scene VRT: " + last_gdal_error());
  out.commit();
}

}  // namespace

bool scene_is_vrt(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".vrt";
}

std::vector<std::filesystem::path> scene_files(const std::filesystem::path& path) {
  if (!scene_is_vrt(path)) return {path};
  return {part_path(path, "elevation"), part_path(path, "category"), path};
}

SceneGeoTiffWriter::SceneGeoTiffWriter(const std::filesystem::path& path, const Scene& grid,
                                       const RasterMetadata& extra_metadata,
                                       const GeoTiffCompression& compression)
    : path_(path), metadata_(extra_metadata), cols_(grid.cols) {
  const Georef georef{grid.geotransform(), grid.crs_wkt};
  metadata_["RIS_SCENE"] = "1";
  const double nan = static_cast<double>(std::numeric_limits<float>::quiet_NaN());
  if (!scene_is_vrt(path)) {
    writer_ = std::make_unique<GeoTiffBlockWriter<float>>(
        path, grid.cols, grid.rows, std::vector<std::string>{"elevation_m", "category"}, &georef,
        nan, metadata_, compression);
    return;
  }
  // The VRT form: the parts carry the grid and no RIS_SCENE (each alone is
  // a DEM and a class raster); the VRT carries the scene's metadata.
  RasterMetadata part_metadata = extra_metadata;
  writer_ = std::make_unique<GeoTiffBlockWriter<float>>(
      part_path(path, "elevation"), grid.cols, grid.rows, std::vector<std::string>{"elevation_m"},
      &georef, nan, part_metadata, compression);
  // The floating-point predictor does not apply to integers; the
  // horizontal difference does.
  GeoTiffCompression integer = compression;
  if (integer.predictor == 3) integer.predictor = 2;
  category_writer_ = std::make_unique<GeoTiffBlockWriter<std::uint16_t>>(
      part_path(path, "category"), grid.cols, grid.rows, std::vector<std::string>{"category"},
      &georef, static_cast<double>(kNoDataCategory), part_metadata, integer);
}

SceneGeoTiffWriter::~SceneGeoTiffWriter() = default;

void SceneGeoTiffWriter::write_rows(const float* elevation_m, const std::uint16_t* category,
                                    const std::uint8_t* valid, int count) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::size_t n = static_cast<std::size_t>(count) * static_cast<std::size_t>(cols_);
  elevation_.resize(n);
  for (std::size_t i = 0; i < n; ++i) elevation_[i] = valid[i] != 0 ? elevation_m[i] : nan;
  if (category_writer_) {
    category_id_.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      category_id_[i] = valid[i] != 0 ? category[i] : kNoDataCategory;
    writer_->write(elevation_.data(), count);
    category_writer_->write(category_id_.data(), count);
    return;
  }
  category_.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    category_[i] = valid[i] != 0 ? static_cast<float>(category[i]) : nan;
  writer_->write({elevation_.data(), category_.data()}, count);
}

void SceneGeoTiffWriter::close() {
  if (!category_writer_) {
    writer_->close();
    return;
  }
  // Parts first, the VRT last; a failure on the way takes back the parts
  // already in place, so a scene is whole or absent.
  std::vector<std::filesystem::path> placed;
  try {
    writer_->close();
    placed.push_back(part_path(path_, "elevation"));
    category_writer_->close();
    placed.push_back(part_path(path_, "category"));
    write_scene_vrt(path_, metadata_);
  } catch (...) {
    std::error_code ec;
    for (const auto& p : placed) std::filesystem::remove(p, ec);
    throw;
  }
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
