#include "ris/scene/scene_source.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <gdal.h>
#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "ris/io/gdal_util.h"
#include "ris/scene/scene_builder.h"
#include "ris/scene/scene_io.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"

namespace ris {

std::map<std::string, std::string> scene_label_metadata(
    const std::string& name, const std::map<std::uint16_t, std::string>& category_names) {
  std::map<std::string, std::string> out;
  if (!name.empty()) out[kSceneNameMetadata] = name;
  if (!category_names.empty()) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [id, label] : category_names) j[std::to_string(id)] = label;
    out[kCategoryNamesMetadata] = j.dump();
  }
  return out;
}

std::map<std::string, std::string> category_label_metadata(
    const std::string& name, const std::set<std::uint16_t>& used,
    const std::map<std::string, std::uint16_t>& library_names) {
  std::map<std::uint16_t, std::string> labels;
  for (const auto& [label, id] : library_names)
    if (used.count(id) != 0) labels[id] = label;
  return scene_label_metadata(name, labels);
}

std::map<std::string, std::string> backscatter_library_metadata(const std::string& library) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path lib = fs::weakly_canonical(library, ec);
  const fs::path data = fs::weakly_canonical(data_dir(), ec);
  const fs::path rel = lib.lexically_relative(data);
  const bool shipped = !rel.empty() && *rel.begin() != "..";
  return {{kBackscatterLibraryMetadata, shipped ? rel.string() : lib.string()}};
}

std::string scene_backscatter_library(const std::string& scene_path) {
  if (scene_path.empty() || is_scene_description(scene_path)) return "";
  const GdalDataset ds = open_raster(scene_path);
  const char* lib = GDALGetMetadataItem(handle(ds), kBackscatterLibraryMetadata, nullptr);
  if (lib == nullptr || *lib == '\0') {
    // An elevation raster alone: every cell is kDefaultCategory (scene.h).
    return GDALGetRasterCount(handle(ds)) < 2 ? (data_dir() / kDefaultCategoryLibrary).string()
                                              : "";
  }
  const std::filesystem::path p(lib);
  return p.is_absolute() ? p.string() : (data_dir() / p).string();
}

namespace {

// Name and labels from a raster's metadata; a malformed item is ignored with
// a warning (the labels only decorate pictures).
void read_labels(const std::string& path, LoadedScene& out) {
  const GdalDataset ds = open_raster(path);
  if (const char* name = GDALGetMetadataItem(handle(ds), kSceneNameMetadata, nullptr)) {
    out.name = name;
  }
  const char* names = GDALGetMetadataItem(handle(ds), kCategoryNamesMetadata, nullptr);
  if (names == nullptr) return;
  try {
    const nlohmann::json j = nlohmann::json::parse(names);
    for (const auto& [key, value] : j.items()) {
      const unsigned long id = std::stoul(key);
      if (id <= kMaxCategory && value.is_string()) {
        out.category_names[static_cast<std::uint16_t>(id)] = value.get<std::string>();
      }
    }
  } catch (const std::exception& e) {
    spdlog::warn("{}: ignoring malformed {} metadata ({})", path, kCategoryNamesMetadata, e.what());
  }
}

}  // namespace

bool is_scene_description(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".toml";
}

LoadedScene load_scene_source(const std::string& path,
                              const std::optional<std::string>& category_path) {
  LoadedScene out;
  if (is_scene_description(path)) {
    if (category_path) {
      throw InputError(*category_path, "--categories",
                       "a category raster applies to elevation rasters, not to a scene "
                       "description (" +
                           path + ") that sets its own categories");
    }
    const SceneDescription d = read_scene_description(path);
    out.scene = build_scene(d);
    out.name = d.name;
    out.category_names = d.category_names;
    out.cultural_objects = cultural_objects(d);
  } else {
    out.scene =
        category_path ? read_scene(path, std::filesystem::path(*category_path)) : read_scene(path);
    read_labels(path, out);
  }
  return out;
}

}  // namespace ris
