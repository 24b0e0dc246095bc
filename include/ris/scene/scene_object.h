// One object of a scene description (a solid, a patch, a checkerboard) and
// the table of object types (DESIGN.md principle 1: an open family, one file
// per member under src/scene/objects/ with its documentation at the top,
// registered by name in one table in src/scene/scene_object.cpp).
//
// Frame. Objects are placed in the grid's local frame: x (metres) east from
// the grid's west edge, y (metres) north from its south edge, so the
// south-west corner of the grid is (0, 0) and cell (row, col) has its centre
// at x = (col + 0.5) dx, y = (rows - row - 0.5) dy. Rotations are
// counter-clockwise seen from above (from +x towards +y), in degrees in the
// file, about the object's anchor (the seed's FAKE rotates its rectangular
// solids about their lower-left corner).
//
// Composition rule (applied by paint(), in file order): in every cell whose
// centre lies in an object's footprint the object's category replaces the
// cell's category, and for solids the elevation becomes
// max(existing elevation, base elevation + object height).
//
// Example (a new object type):
//   // src/scene/objects/cone.cpp: doc, a struct with height_at(x, y), and
//   std::unique_ptr<SceneObject> parse_cone(ConfigTable& t, const GridExtent& g);
//   // then one line in the table in src/scene/scene_object.cpp:
//   {"cone", "a right circular cone", parse_cone},
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "ris/io/config_table.h"
#include "ris/scene/cultural_object.h"
#include "ris/scene/scene.h"

namespace ris {

// Axis-aligned bounds of a footprint in the grid's local frame, metres.
struct Bounds {
  double x_min_m = 0.0;
  double y_min_m = 0.0;
  double x_max_m = 0.0;
  double y_max_m = 0.0;
};

// The grid's extent in its local frame, metres (for defaults such as a
// checkerboard that covers the whole grid).
struct GridExtent {
  double width_m = 0.0;   // cols * cell size, along x
  double height_m = 0.0;  // rows * cell size, along y
};

// An anchor and a rotation: maps the local frame to the object's own frame
// (u along its length, v along its width), both in metres.
struct Placement {
  double x0_m = 0.0;
  double y0_m = 0.0;
  double cos_a = 1.0;
  double sin_a = 0.0;

  static Placement at(double x0_m, double y0_m, double rotation_rad);
  // Object coordinates (u, v) of a local-frame point: the inverse rotation.
  std::pair<double, double> to_object(double x_m, double y_m) const {
    const double dx = x_m - x0_m;
    const double dy = y_m - y0_m;
    return {cos_a * dx + sin_a * dy, -sin_a * dx + cos_a * dy};
  }
  // Bounds of the object-frame rectangle [u0, u1] x [v0, v1] once placed.
  Bounds bounds_of(double u0_m, double v0_m, double u1_m, double v1_m) const;
};

// A parsed, checked object ready to be painted into a scene.
class SceneObject {
 public:
  virtual ~SceneObject() = default;
  // The type name as written in the file ("pyramid").
  virtual std::string_view type() const = 0;
  // Conservative bounds of the footprint, local frame.
  virtual Bounds bounds() const = 0;
  // Paints the object by the composition rule; base_elevation_m is the
  // grid's base plane. Returns the number of cells whose centre lies in the
  // footprint (0 when the object misses every cell centre).
  virtual std::size_t paint(Scene& scene, float base_elevation_m) const = 0;
  // The smallest detail the object draws, metres: by default the narrower
  // side of its bounds; a checkerboard's square. A detail smaller than a
  // cell is lost (cells take the object only where their centre falls).
  virtual double smallest_feature_m() const {
    const Bounds b = bounds();
    return std::min(b.x_max_m - b.x_min_m, b.y_max_m - b.y_min_m);
  }
  // The object as a 3-D cultural object (buildings, reflectors;
  // ris/scene/cultural_object.h) for the ray tracer, in the description's
  // local frame; none for the grid's solids. base_elevation_m: the grid's
  // base plane, where a building's walls stand.
  virtual std::optional<CulturalObject> cultural(float base_elevation_m) const {
    (void)base_elevation_m;
    return std::nullopt;
  }
};

// One entry of the object-type table.
using ObjectParser = std::unique_ptr<SceneObject> (*)(ConfigTable& table, const GridExtent& grid);
struct ObjectType {
  std::string_view name;
  std::string_view summary;  // one line: the parameters, for help and errors
  ObjectParser parse;
};

// Every object type, in the order of the documentation.
std::span<const ObjectType> object_types();

// Parses one [[object]] table (its `type` key picks the entry); throws
// InputError naming the file and key for an unknown type, a missing,
// misspelled or impossible parameter.
std::unique_ptr<SceneObject> parse_scene_object(ConfigTable& table, const GridExtent& grid);

// Checked parameters shared by the object types. Each throws InputError
// naming the file and key.
namespace object_params {
// A length > 0 ("20 ft" or metres).
double positive_length_m(ConfigTable& t, const std::string& key);
// A length >= 0.
double non_negative_length_m(ConfigTable& t, const std::string& key);
// A coordinate (any sign), metres.
double coordinate_m(ConfigTable& t, const std::string& key);
// Optional rotation, default 0; any value.
double rotation_rad(ConfigTable& t, const std::string& key);
// A slope angle strictly between 0 and 90 degrees.
double slope_rad(ConfigTable& t, const std::string& key);
// A category id 0..kMaxCategory.
std::uint16_t category(ConfigTable& t, const std::string& key);
// A non-empty array of category ids.
std::vector<std::uint16_t> categories(ConfigTable& t, const std::string& key);
}  // namespace object_params

}  // namespace ris
