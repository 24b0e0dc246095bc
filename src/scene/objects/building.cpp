// building: a cultural object with a polygon footprint and a flat roof
// (issue 32; docs/objects.md "Objects in a scene").
//
//   type = "building"
//   footprint        [[x, y], ...]: >= 3 vertices of a simple polygon (either
//                    orientation; not closed: the last joins the first),
//                    metres or strings with a unit
//   height           > 0, or storeys (integer >= 1) x storey_height (default 3 m)
//   roof             "flat" (the only roof built yet)
//   category         category id of the footprint (the roof's diffuse return)
//   wall_material, roof_material, ground_material
//                    names in the material library (default "concrete";
//                    data/materials/materials.toml)
//
// Painted as a solid: h(x, y) = height inside the footprint (its cell
// centres, boundaries included), composed by the scene's rule; kept as a
// 3-D object (ris/scene/cultural_object.h) for the ray tracer.
#include <fmt/format.h>

#include <cmath>

#include "ris/util/units.h"
#include "scene/objects/object_types.h"
#include "scene/objects/paint_cells.h"

namespace ris::detail {
namespace {

using Point = std::array<double, 2>;

double signed_area_m2(const std::vector<Point>& p) {
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point& u = p[i];
    const Point& v = p[(i + 1) % p.size()];
    a += u[0] * v[1] - v[0] * u[1];
  }
  return 0.5 * a;
}

double cross(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

// Proper or touching intersection of segments ab and cd.
bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  const auto on = [](const Point& p, const Point& q, const Point& r, double side) {
    return side == 0.0 && std::min(p[0], q[0]) <= r[0] && r[0] <= std::max(p[0], q[0]) &&
           std::min(p[1], q[1]) <= r[1] && r[1] <= std::max(p[1], q[1]);
  };
  return on(c, d, a, d1) || on(c, d, b, d2) || on(a, b, c, d3) || on(a, b, d, d4);
}

// Index pair of two non-adjacent edges that meet, or -1.
int first_self_intersection(const std::vector<Point>& p) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      if (j == i + 1 || (i == 0 && j == n - 1)) continue;  // neighbours share a vertex
      if (segments_meet(p[i], p[(i + 1) % n], p[j], p[(j + 1) % n])) return static_cast<int>(i);
    }
  }
  return -1;
}

// Even-odd rule; a point on an edge counts as inside (boundaries included,
// as every object's footprint).
bool inside(const std::vector<Point>& p, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
    const Point& a = p[i];
    const Point& b = p[j];
    if (cross(a, b, {x, y}) == 0.0 && std::min(a[0], b[0]) <= x && x <= std::max(a[0], b[0]) &&
        std::min(a[1], b[1]) <= y && y <= std::max(a[1], b[1])) {
      return true;
    }
    if ((a[1] > y) != (b[1] > y) && x < (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) + a[0]) in = !in;
  }
  return in;
}

double length_of(ConfigTable& t, const toml::node& n, const std::string& key) {
  if (const auto* v = n.as_floating_point()) return v->get();
  if (const auto* v = n.as_integer()) return static_cast<double>(v->get());
  if (const auto* s = n.as_string()) {
    try {
      return parse_quantity(s->get(), Quantity::length);
    } catch (const std::exception& e) {
      t.fail(key, e.what());
    }
  }
  t.fail(key, "expected a length (metres, or a string such as \"20 ft\")");
}

std::vector<Point> parse_footprint(ConfigTable& t) {
  const toml::node* raw = t.raw("footprint");
  if (raw == nullptr) t.fail("footprint", "missing: expected [[x, y], ...], at least 3 vertices");
  const toml::array* arr = raw->as_array();
  if (arr == nullptr) t.fail("footprint", "expected an array of [x, y] vertices");
  std::vector<Point> p;
  for (std::size_t i = 0; i < arr->size(); ++i) {
    const std::string key = fmt::format("footprint[{}]", i);
    const toml::array* xy = (*arr)[i].as_array();
    if (xy == nullptr || xy->size() != 2) t.fail(key, "expected a vertex [x, y]");
    const Point v{length_of(t, *xy->get(0), key), length_of(t, *xy->get(1), key)};
    if (!std::isfinite(v[0]) || !std::isfinite(v[1])) t.fail(key, "must be finite");
    p.push_back(v);
  }
  // A closing vertex equal to the first is accepted (GeoJSON rings repeat it).
  if (p.size() > 3 && p.front() == p.back()) p.pop_back();
  if (p.size() < 3) {
    t.fail("footprint", fmt::format("has {} vertices; a footprint needs at least 3", p.size()));
  }
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p[i] == p[(i + 1) % p.size()]) {
      t.fail(fmt::format("footprint[{}]", i), "repeats the next vertex; drop one of them");
    }
  }
  if (const int e = first_self_intersection(p); e >= 0) {
    t.fail("footprint",
           fmt::format("crosses itself (the edge from vertex {} meets another edge); expected a "
                       "simple polygon, its vertices in order around it",
                       e));
  }
  if (std::abs(signed_area_m2(p)) <= 0.0) t.fail("footprint", "has no area");
  if (signed_area_m2(p) < 0.0) std::reverse(p.begin(), p.end());  // counter-clockwise
  return p;
}

double building_height_m(ConfigTable& t) {
  if (t.has("height")) {
    if (t.has("storeys")) t.fail("storeys", "give height or storeys, not both");
    return object_params::positive_length_m(t, "height");
  }
  if (!t.has("storeys")) {
    t.fail("height", "missing: give height, or storeys (x storey_height, default 3 m)");
  }
  const std::int64_t storeys = t.get_int("storeys");
  if (storeys < 1 || storeys > 1000) t.fail("storeys", "expected an integer 1..1000");
  const double storey_m =
      t.has("storey_height") ? object_params::positive_length_m(t, "storey_height") : 3.0;
  return static_cast<double>(storeys) * storey_m;
}

class Building final : public SceneObject {
 public:
  Building(CulturalObject c, std::uint16_t category) : c_(std::move(c)), category_(category) {}
  std::string_view type() const override { return "building"; }
  Bounds bounds() const override {
    Bounds b{INFINITY, INFINITY, -INFINITY, -INFINITY};
    for (const Point& p : c_.footprint_m) {
      b.x_min_m = std::min(b.x_min_m, p[0]);
      b.y_min_m = std::min(b.y_min_m, p[1]);
      b.x_max_m = std::max(b.x_max_m, p[0]);
      b.y_max_m = std::max(b.y_max_m, p[1]);
    }
    return b;
  }
  std::size_t paint(Scene& scene, float base_elevation_m) const override {
    const double base_m = base_elevation_m;
    return paint_cells(scene, bounds(), [&](double x_m, double y_m, float& z, std::uint16_t& cat) {
      if (!inside(c_.footprint_m, x_m, y_m)) return false;
      compose_solid(z, cat, base_m, c_.height_m, category_);
      return true;
    });
  }
  std::optional<CulturalObject> cultural(float base_elevation_m) const override {
    CulturalObject c = c_;
    c.base_m = base_elevation_m;
    return c;
  }

 private:
  CulturalObject c_;
  std::uint16_t category_;
};

}  // namespace

}  // namespace ris::detail

namespace ris {

bool point_in_footprint(const std::vector<std::array<double, 2>>& footprint_m, double x_m,
                        double y_m) {
  return detail::inside(footprint_m, x_m, y_m);
}

void move_to_world(std::vector<CulturalObject>& objects, double x0_m, double y0_m) {
  for (CulturalObject& o : objects) {
    for (std::array<double, 2>& p : o.footprint_m) {
      p[0] += x0_m;
      p[1] += y0_m;
    }
    o.x_m += x0_m;
    o.y_m += y0_m;
  }
}

}  // namespace ris

namespace ris::detail {

std::unique_ptr<SceneObject> parse_building(ConfigTable& t, const GridExtent&) {
  CulturalObject c;
  c.kind = CulturalKind::building;
  c.source = t.file();
  c.footprint_m = parse_footprint(t);
  c.height_m = building_height_m(t);
  const std::string roof = t.get_string_or("roof", "flat");
  if (roof != "flat") {
    t.fail("roof", fmt::format("\"{}\": only flat roofs are built yet (gabled and hipped roofs "
                               "are not); use roof = \"flat\"",
                               roof));
  }
  c.wall_material = t.get_string_or("wall_material", c.wall_material);
  c.roof_material = t.get_string_or("roof_material", c.roof_material);
  c.ground_material = t.get_string_or("ground_material", c.ground_material);
  return std::make_unique<Building>(std::move(c), object_params::category(t, "category"));
}

}  // namespace ris::detail
