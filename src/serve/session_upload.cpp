// Session::upload: a DEM, a land-cover raster or a scene file brought to the
// page (ris/serve/session.h). The bytes land in the session's own working
// folder, one sub-folder per upload, under a plain name; from there they are
// opened exactly as the command line opens a file it is given
// (open_raster's checks: a regular file, a VRT's sources and GDAL's side
// files inside that sub-folder, ris/io/file_references.h; the grid's size
// against memory), so an upload reaches nothing a command-line argument
// could not.
#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <regex>

#include "ris/backscatter/library.h"
#include "ris/scene/dem_import.h"
#include "ris/scene/landcover.h"
#include "ris/scene/scene_io.h"
#include "ris/scene/scene_source.h"
#include "ris/serve/session.h"
#include "ris/sim/run.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"

namespace ris {
namespace {

constexpr const char* kUpload = "upload";
// Upload folders kept; older ones are removed (their scenes stay in memory).
constexpr std::uint64_t kKeptUploads = 8;

const std::vector<std::string> kRasterExtensions = {".tif", ".tiff", ".hgt", ".dem", ".asc",
                                                    ".dt0", ".dt1",  ".dt2", ".img", ".vrt"};

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

std::string joined(const std::vector<std::string>& v) {
  std::string out;
  for (const std::string& e : v) out += (out.empty() ? "" : ", ") + e;
  return out;
}

}  // namespace

std::filesystem::path Session::store_upload(const std::string& name, const std::string& bytes,
                                            const std::vector<std::string>& extensions) {
  // A plain file name only (GDAL reads some formats' georeferencing from
  // it, N41E012.hgt): no folder, no leading dot, no "..".
  static const std::regex plain("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");
  if (!std::regex_match(name, plain) || name.find("..") != std::string::npos) {
    throw InputError(kUpload, "name",
                     "expected a plain file name (letters, digits, '.', '-' and '_', at most 64, "
                     "no folder), got \"" +
                         name + "\"");
  }
  const std::string ext = lower(std::filesystem::path(name).extension().string());
  if (std::find(extensions.begin(), extensions.end(), ext) == extensions.end()) {
    throw InputError(kUpload, "name",
                     fmt::format("\"{}\": expected a file ending in {}", name, joined(extensions)));
  }
  if (bytes.empty()) throw InputError(kUpload, "", "the uploaded file is empty");
  const std::uint64_t n = ++uploads_;
  if (n > kKeptUploads) {
    std::error_code ec;
    std::filesystem::remove_all(work_dir_ / fmt::format("upload-{}", n - kKeptUploads), ec);
  }
  const std::filesystem::path dir = work_dir_ / fmt::format("upload-{}", n);
  std::filesystem::create_directory(dir);
  const std::filesystem::path path = dir / name;
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!out.flush()) throw InputError(kUpload, "", "cannot store the uploaded file");
  return path;
}

Session::SceneState Session::landcover_scene(const std::filesystem::path& raster,
                                             const std::string& mapping) {
  if (scene_.editable || scene_.scene->crs_wkt.empty()) {
    throw InputError(kUpload, "kind",
                     "land cover is laid on a georeferenced raster scene: upload a DEM first");
  }
  const std::string name = mapping.empty() ? "esa-worldcover.toml" : mapping;
  const auto it = landcover_mappings_.find(name);
  if (it == landcover_mappings_.end()) {
    throw InputError(kUpload, "mapping", "unknown land-cover mapping \"" + name + "\"");
  }
  const LandCoverMapping m = read_landcover_mapping(it->second);
  auto scene = std::make_shared<Scene>(*scene_.scene);
  apply_landcover(*scene, raster, m);
  SceneState next = scene_;
  next.scene = std::move(scene);
  next.version = ++scene_versions_;
  if (!m.library.empty()) use_library(m.library);
  return next;
}

nlohmann::json Session::upload(const std::string& kind, const std::string& name,
                               const std::string& mapping, const std::string& bytes) {
  std::lock_guard lock(mutex_);
  // What a failed upload must not change.
  const std::string old_library = backscatter_name_;
  const std::shared_ptr<const Sigma0Source> old_sigma0 = sigma0_;
  try {
    SceneState next;
    if (kind == "dem") {
      const std::filesystem::path dem = store_upload(name, bytes, kRasterExtensions);
      // As `ris scene import DEM` then `ris simulate --scene` on its output:
      // every cell the default category, the scene naming its library.
      DemImportOptions options;
      options.crs_key = "crs";
      const ImportedDem imported = import_dem(dem, options);
      RasterMetadata metadata = imported.metadata;
      const std::string library = (data_dir() / kDefaultCategoryLibrary).string();
      for (auto& [k, v] : backscatter_library_metadata(library)) metadata[k] = v;
      const std::filesystem::path scene_file = dem.parent_path() / "scene.tif";
      write_scene_geotiff(imported.scene, scene_file, metadata);
      next = scene_from_file(scene_file.string());
      use_library(backscatter_library_for("", scene_file.string()));
    } else if (kind == "landcover") {
      next = landcover_scene(store_upload(name, bytes, kRasterExtensions), mapping);
    } else if (kind == "scene") {
      std::vector<std::string> extensions = {".toml", ".tif", ".tiff"};
      const std::filesystem::path file = store_upload(name, bytes, extensions);
      next = scene_from_file(file.string());
      use_library(backscatter_library_for("", file.string()));
    } else {
      throw InputError(kUpload, "kind", "expected dem, landcover or scene, got \"" + kind + "\"");
    }
    nlohmann::json out = apply_scene(std::move(next), true);
    out["uploaded"] = name;
    out["backscatter"] = backscatter_name_;
    return out;
  } catch (...) {
    backscatter_name_ = old_library;
    sigma0_ = old_sigma0;
    throw;
  }
}

}  // namespace ris
