// The scene builder: a TOML scene description -> a Scene (the seed's program
// FAKE, Appendix B, with each solid evaluated analytically at cell centres so
// that no holes appear). The file format is documented in
// docs/scene-format.md; each object type in src/scene/objects/<type>.cpp.
//
//   [grid]
//   rows = 700                 # along y (north-south)
//   cols = 1000                # along x (east-west)
//   cell_size = "20 ft"        # square cells; a number is metres
//   base_elevation = 0         # optional, default 0 m
//   base_category = 1          # optional, default 0
//   origin = [500000, 4200000] # optional: world x, y of the south-west corner
//   crs = "EPSG:32614"         # optional: anything GDAL's SetFromUserInput reads
//
//   [category_names]           # optional labels for legends
//   1 = "wheat stubble"
//
//   [[object]]
//   type = "pyramid"
//   x = "1510 ft"              # positions from the grid's south-west corner
//   y = "9310 ft"
//   base = "2400 ft"
//   height = "2000 ft"
//   category = 4
//
// Parsing is separate from building (DESIGN.md principle 2): the whole file
// is checked, and the grid's memory estimate refused if too large, before a
// cell is allocated.
//
// Example:
//   ris::SceneDescription d = ris::read_scene_description("data/scenes/ku-geometric.toml");
//   ris::Scene s = ris::build_scene(d);
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "ris/scene/scene.h"
#include "ris/scene/scene_object.h"

namespace ris {

struct GridSpec {
  int rows = 0;
  int cols = 0;
  double cell_m = 0.0;  // square cells
  float base_elevation_m = 0.0f;
  std::uint16_t base_category = 0;
  double origin_x_m = 0.0;  // world coordinates of the grid's south-west corner
  double origin_y_m = 0.0;
  std::string crs_wkt;  // empty: a local frame
};

struct SceneDescription {
  std::string source;       // the file, for messages
  std::string name;         // optional top-level `name`
  std::string description;  // optional top-level `description`
  GridSpec grid;
  // Optional [category_names] table ("1" = "wheat stubble"): labels for
  // legends only; backscatter models bind to the ids.
  std::map<std::uint16_t, std::string> category_names;
  std::vector<std::unique_ptr<SceneObject>> objects;
  std::vector<std::string> object_labels;  // "object[3] (pyramid)", for messages
};

// Parses and checks a scene description. Throws InputError naming the file
// and key for any bad input (unknown type or key, missing key, impossible
// size, slope or category, a grid too large for memory).
SceneDescription parse_scene_description(const toml::table& doc, const std::string& source);
SceneDescription read_scene_description(const std::string& path);

// The description's buildings and reflectors (ris/scene/cultural_object.h)
// in world coordinates, those whose bounds meet the grid (the builder warns
// of the others), labelled as its messages label them.
std::vector<CulturalObject> cultural_objects(const SceneDescription& description);

// Builds the scene: the base plane, then each object in file order by the
// composition rule (scene_object.h). An object that covers no cell centre of
// the grid (wholly outside it, or too small) is skipped with a warning that
// names it.
Scene build_scene(const SceneDescription& description);

// read_scene_description + build_scene.
Scene build_scene_file(const std::string& path);

}  // namespace ris
