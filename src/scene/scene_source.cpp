#include "ris/scene/scene_source.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "ris/io/scene_io.h"
#include "ris/scene/scene_builder.h"
#include "ris/util/error.h"

namespace ris {

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
  } else if (category_path) {
    out.scene = read_scene(path, std::filesystem::path(*category_path));
  } else {
    out.scene = read_scene(path);
  }
  return out;
}

}  // namespace ris
