// Painting categories: analytic cell counts for a brush and a polygon, cells
// without data untouched, bad strokes refused naming the key.
#include "ris/serve/category_paint.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "ris/serve/json_toml.h"
#include "ris/util/error.h"

namespace ris {
namespace {

std::size_t count(const Scene& s, std::uint16_t category) {
  return static_cast<std::size_t>(std::count(s.category.begin(), s.category.end(), category));
}

TEST(CategoryPaint, BrushCoversTheCellsWithinItsRadius) {
  Scene s = Scene::flat(20, 20, 1.0, 0.0f, 1);
  // Centred on cell (10, 10)'s centre with radius 2: the cell centres within
  // distance 2 of a lattice point are the 13 of x^2 + y^2 <= 4.
  const PaintStroke stroke =
      parse_paint_stroke(json_body_to_toml(R"({"category": 7, "brush": [[10.5, 10.5]],
                                               "radius": 2})",
                                           "request body"));
  EXPECT_EQ(paint_categories(s, stroke), 13u);
  EXPECT_EQ(count(s, 7), 13u);
  EXPECT_EQ(s.category[s.index(10, 12)], 7);
  EXPECT_EQ(s.category[s.index(11, 12)], 1);
}

TEST(CategoryPaint, PolygonCoversTheCellCentresInside) {
  Scene s = Scene::flat(20, 30, 1.0, 0.0f, 1);
  s.valid[s.index(3, 3)] = 0;  // no data: stays as it is
  // The rectangle cols 2..12, rows 1..6: centres 2.5..11.5 x 1.5..5.5 = 10 x 5.
  const PaintStroke stroke = parse_paint_stroke(json_body_to_toml(
      R"({"category": 4, "polygon": [[2, 1], [12, 1], [12, 6], [2, 6]]})", "request body"));
  EXPECT_EQ(paint_categories(s, stroke), 49u);
  EXPECT_EQ(count(s, 4), 49u);
  EXPECT_EQ(s.category[s.index(3, 3)], 1);
  // A right triangle with legs of 10: the centres with x + y < 10, i.e.
  // c + r <= 8, 45 of them (the 10 on the hypotenuse, c + r = 9, are outside).
  Scene t = Scene::flat(10, 10, 1.0, 0.0f, 1);
  const PaintStroke tri = parse_paint_stroke(
      json_body_to_toml(R"({"category": 2, "polygon": [[0, 0], [10, 0], [0, 10]]})", "request"));
  EXPECT_EQ(paint_categories(t, tri), 45u);
}

TEST(CategoryPaint, BadStrokesAreRefused) {
  for (const char* body :
       {R"({"category": 3})",
        R"({"category": 3, "brush": [[1, 2]], "polygon": [[0,0],[1,0],[0,1]]})",
        R"({"category": 70000, "brush": [[1, 2]]})", R"({"category": 3, "brush": [[1]]})",
        R"({"category": 3, "polygon": [[0, 0], [1, 1]]})",
        R"({"category": 3, "brush": [[1, 2]], "radius": -1})",
        R"({"category": 3, "brush": [[1, 2]], "colour": "red"})"}) {
    EXPECT_THROW(parse_paint_stroke(json_body_to_toml(body, "request body")), InputError) << body;
  }
}

}  // namespace
}  // namespace ris
