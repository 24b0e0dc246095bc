#include "ris/scene/scene_object.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "ris/util/error.h"
#include "ris/util/spelling.h"
#include "ris/util/units.h"
#include "scene/objects/object_types.h"

namespace ris {

Placement Placement::at(double x0_m, double y0_m, double rotation_rad) {
  Placement p;
  p.x0_m = x0_m;
  p.y0_m = y0_m;
  p.cos_a = std::cos(rotation_rad);
  p.sin_a = std::sin(rotation_rad);
  return p;
}

Bounds Placement::bounds_of(double u0_m, double v0_m, double u1_m, double v1_m) const {
  // Forward rotation of the rectangle's four corners: x = x0 + u cos - v sin,
  // y = y0 + u sin + v cos.
  const std::array<std::pair<double, double>, 4> corners{
      {{u0_m, v0_m}, {u1_m, v0_m}, {u0_m, v1_m}, {u1_m, v1_m}}};
  Bounds b{INFINITY, INFINITY, -INFINITY, -INFINITY};
  for (const auto& [u, v] : corners) {
    const double x = x0_m + u * cos_a - v * sin_a;
    const double y = y0_m + u * sin_a + v * cos_a;
    b.x_min_m = std::min(b.x_min_m, x);
    b.x_max_m = std::max(b.x_max_m, x);
    b.y_min_m = std::min(b.y_min_m, y);
    b.y_max_m = std::max(b.y_max_m, y);
  }
  return b;
}

std::span<const ObjectType> object_types() {
  // The one table of object types (DESIGN.md principle 1). Each parser lives
  // in src/scene/objects/<name>.cpp with its documentation at the top.
  static constexpr std::array<ObjectType, 10> kTypes{{
      {"patch", "x, y, length, width, [rotation], category: a flat rectangle of one category",
       detail::parse_patch},
      {"box", "x, y, length, width, height, [rotation], category: a block (the seed's cube)",
       detail::parse_box},
      {"wedge",
       "x, y, length, height, front_slope, top_width, back_slope, [rotation], category: a ridge",
       detail::parse_wedge},
      {"pyramid", "x, y, base, height, [rotation], category: a square pyramid",
       detail::parse_pyramid},
      {"hemisphere", "x, y, radius, category: a half sphere", detail::parse_hemisphere},
      {"cylinder", "x, y, radius, length, [rotation], category: a half cylinder lying down",
       detail::parse_cylinder},
      {"tower", "x, y, radius, height, category: a vertical cylinder", detail::parse_tower},
      {"checkerboard",
       "square, categories, [x, y, length, width, rotation]: squares cycling through categories",
       detail::parse_checkerboard},
      {"building",
       "footprint, height (or storeys), [roof], category, [wall/roof/ground_material]: a "
       "building, painted and ray-traced",
       detail::parse_building},
      {"reflector",
       "shape, x, y, size, [width, height, azimuth, tilt, roll, material]: a canonical "
       "reflector, ray-traced",
       detail::parse_reflector},
  }};
  return kTypes;
}

std::unique_ptr<SceneObject> parse_scene_object(ConfigTable& table, const GridExtent& grid) {
  const std::string type = table.get_string("type");
  // Without regard to case, as every enum value (ConfigTable::get_enum).
  for (const ObjectType& entry : object_types()) {
    if (same_letters(entry.name, type)) {
      std::unique_ptr<SceneObject> object = entry.parse(table, grid);
      table.finish();
      return object;
    }
  }
  std::string known;
  std::vector<std::string> names;
  for (const ObjectType& entry : object_types()) {
    if (!known.empty()) known += ", ";
    known += entry.name;
    names.emplace_back(entry.name);
  }
  table.fail("type", fmt::format("unknown object type \"{}\"{} (known: {})", type,
                                 did_you_mean(type, names), known));
}

namespace object_params {

double positive_length_m(ConfigTable& t, const std::string& key) {
  const double v = t.get_quantity(key, Quantity::length);
  if (!(v > 0.0) || !std::isfinite(v)) {
    t.fail(key, fmt::format("must be a length > 0, got {} m", v));
  }
  return v;
}

double non_negative_length_m(ConfigTable& t, const std::string& key) {
  const double v = t.get_quantity(key, Quantity::length);
  if (!(v >= 0.0) || !std::isfinite(v)) {
    t.fail(key, fmt::format("must be a length >= 0, got {} m", v));
  }
  return v;
}

double coordinate_m(ConfigTable& t, const std::string& key) {
  const double v = t.get_quantity(key, Quantity::length);
  if (!std::isfinite(v)) t.fail(key, "must be a finite length");
  return v;
}

double rotation_rad(ConfigTable& t, const std::string& key) {
  const double v = t.get_quantity_or(key, Quantity::angle, 0.0);
  if (!std::isfinite(v)) t.fail(key, "must be a finite angle");
  return v;
}

double slope_rad(ConfigTable& t, const std::string& key) {
  const double v = t.get_quantity(key, Quantity::angle);
  if (!(v > 0.0 && v < kPi / 2.0)) {
    t.fail(key, fmt::format("a slope must be strictly between 0 and 90 deg, got {:g} deg",
                            rad_to_deg(v)));
  }
  return v;
}

namespace {
std::uint16_t category_value(const toml::node& node, ConfigTable& t, const std::string& key) {
  const auto* i = node.as_integer();
  if (i == nullptr) {
    t.fail(key, fmt::format("expected an integer category id 0..{}", kMaxCategory));
  }
  const std::int64_t v = i->get();
  if (v < 0 || v > kMaxCategory) {
    t.fail(key, fmt::format("category {} out of range: expected 0..{}", v, kMaxCategory));
  }
  return static_cast<std::uint16_t>(v);
}
}  // namespace

std::uint16_t category(ConfigTable& t, const std::string& key) {
  const toml::node* node = t.raw(key);
  if (node == nullptr) t.fail(key, "missing required key");
  return category_value(*node, t, key);
}

std::vector<std::uint16_t> categories(ConfigTable& t, const std::string& key) {
  const toml::node* node = t.raw(key);
  if (node == nullptr) t.fail(key, "missing required key");
  const toml::array* arr = node->as_array();
  if (arr == nullptr || arr->empty()) {
    t.fail(key, "expected a non-empty array of category ids, e.g. [1, 2, 3]");
  }
  std::vector<std::uint16_t> out;
  for (const toml::node& element : *arr) out.push_back(category_value(element, t, key));
  return out;
}

}  // namespace object_params
}  // namespace ris
