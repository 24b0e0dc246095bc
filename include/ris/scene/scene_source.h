// A scene from whatever file the user names: a scene description (.toml) is
// built (scene_builder.h), anything else is read through GDAL (scene_io.h: a
// ris scene GeoTIFF, or an elevation model with an optional category raster
// on the same grid). Every command that takes a scene should load it here so
// they all accept the same inputs.
//
// Example:
//   ris::LoadedScene in = ris::load_scene_source(path);   // .toml or raster
//   simulate(in.scene, ...);
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "ris/scene/cultural_object.h"
#include "ris/scene/scene.h"

namespace ris {

struct LoadedScene {
  Scene scene;
  std::string name;                                     // description's `name`, or ""
  std::map<std::uint16_t, std::string> category_names;  // description's labels, or empty
  // A description's buildings and reflectors in world coordinates
  // (ris/scene/cultural_object.h), those whose bounds meet the grid; none
  // for a raster (a GeoTIFF keeps the painted grid only).
  std::vector<CulturalObject> cultural_objects;
};

// GeoTIFF metadata items that carry a description's name and category
// labels into a built scene file, so pictures of it keep their legend:
// RIS_SCENE_NAME (text) and RIS_CATEGORY_NAMES (a JSON object, id -> label).
inline constexpr const char* kSceneNameMetadata = "RIS_SCENE_NAME";
inline constexpr const char* kCategoryNamesMetadata = "RIS_CATEGORY_NAMES";

// The backscatter library whose ids the scene's categories are (written by
// `ris scene import` and `ris scene fractal`): a path relative to the data
// folder for a shipped library, else as given. `ris simulate` uses it when
// no --backscatter is given.
inline constexpr const char* kBackscatterLibraryMetadata = "RIS_BACKSCATTER_LIBRARY";

// The metadata item above for a library path: relative to the data folder
// when the library is inside it.
std::map<std::string, std::string> backscatter_library_metadata(const std::string& library);

// The library a scene raster names (kBackscatterLibraryMetadata, resolved
// against the data folder); for an elevation raster alone (one band) the
// library of kDefaultCategory; "" for a description or another raster.
std::string scene_backscatter_library(const std::string& scene_path);

// The metadata items above for a name and labels (empty ones left out).
std::map<std::string, std::string> scene_label_metadata(
    const std::string& name, const std::map<std::uint16_t, std::string>& category_names);

// The same with the labels of the categories `used` taken from a library's
// names (name -> id; the ids it lacks go unlabelled).
std::map<std::string, std::string> category_label_metadata(
    const std::string& name, const std::set<std::uint16_t>& used,
    const std::map<std::string, std::uint16_t>& library_names);

// Whether a path names a scene description (extension .toml, any case).
bool is_scene_description(const std::string& path);

// A raster's name and labels come from the metadata items above when it has
// them. category_path applies to rasters only (an InputError naming it otherwise).
LoadedScene load_scene_source(const std::string& path,
                              const std::optional<std::string>& category_path = std::nullopt);

}  // namespace ris
