#include "ris/serve/category_paint.h"

#include <algorithm>
#include <cmath>

#include "ris/io/config_table.h"
#include "ris/util/error.h"

namespace ris {
namespace {

std::vector<std::array<double, 2>> points(ConfigTable& t, const std::string& key) {
  const toml::node* node = t.raw(key);
  const toml::array* list = node != nullptr ? node->as_array() : nullptr;
  if (list == nullptr) t.fail(key, "expected an array of [col, row] pairs");
  std::vector<std::array<double, 2>> out;
  for (const toml::node& p : *list) {
    const toml::array* pair = p.as_array();
    if (pair == nullptr || pair->size() != 2 || !(*pair)[0].is_number() ||
        !(*pair)[1].is_number()) {
      t.fail(key, "expected an array of [col, row] pairs");
    }
    out.push_back({(*pair)[0].value<double>().value(), (*pair)[1].value<double>().value()});
  }
  return out;
}

// Even-odd rule: a horizontal ray from (x, y) crosses the edges an odd number
// of times when the point is inside.
bool inside(const std::vector<std::array<double, 2>>& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const auto& a = poly[i];
    const auto& b = poly[j];
    if ((a[1] > y) != (b[1] > y) && x < (b[0] - a[0]) * (y - a[1]) / (b[1] - a[1]) + a[0]) {
      in = !in;
    }
  }
  return in;
}

}  // namespace

PaintStroke parse_paint_stroke(const toml::table& body) {
  ConfigTable t(body, "request body", "");
  PaintStroke s;
  const std::int64_t c = t.get_int("category");
  if (c < 0 || c > kMaxCategory) t.fail("category", "expected a category id 0..65534");
  s.category = static_cast<std::uint16_t>(c);
  if (t.has("polygon") == t.has("brush")) {
    throw InputError("request body", "polygon", "give one of polygon and brush");
  }
  if (t.has("polygon")) {
    s.polygon = points(t, "polygon");
    if (s.polygon.size() < 3) t.fail("polygon", "expected at least 3 vertices");
  } else {
    s.brush_centres = points(t, "brush");
    s.brush_radius_cells = t.get_double_or("radius", 1.0);
    if (!(s.brush_radius_cells > 0.0 && s.brush_radius_cells <= 1000.0)) {
      t.fail("radius", "expected a brush radius of 0 to 1000 cells");
    }
  }
  t.finish();
  return s;
}

std::size_t paint_categories(Scene& scene, const PaintStroke& s) {
  std::size_t painted = 0;
  auto paint = [&](int r, int c) {
    const std::size_t i = scene.index(r, c);
    if (scene.valid[i] == 0) return;
    scene.category[i] = s.category;
    ++painted;
  };
  if (!s.polygon.empty()) {
    for (int r = 0; r < scene.rows; ++r) {
      for (int c = 0; c < scene.cols; ++c) {
        if (inside(s.polygon, c + 0.5, r + 0.5)) paint(r, c);
      }
    }
    return painted;
  }
  // Each cell once, however many centres cover it.
  std::vector<std::uint8_t> done(scene.size(), 0);
  const double rad = s.brush_radius_cells;
  for (const auto& [x, y] : s.brush_centres) {
    const int r0 = std::max(0, static_cast<int>(std::floor(y - rad)));
    const int r1 = std::min(scene.rows - 1, static_cast<int>(std::ceil(y + rad)));
    const int c0 = std::max(0, static_cast<int>(std::floor(x - rad)));
    const int c1 = std::min(scene.cols - 1, static_cast<int>(std::ceil(x + rad)));
    for (int r = r0; r <= r1; ++r) {
      for (int c = c0; c <= c1; ++c) {
        const double dx = c + 0.5 - x;
        const double dy = r + 0.5 - y;
        if (dx * dx + dy * dy > rad * rad || done[scene.index(r, c)]) continue;
        done[scene.index(r, c)] = 1;
        paint(r, c);
      }
    }
  }
  return painted;
}

}  // namespace ris
