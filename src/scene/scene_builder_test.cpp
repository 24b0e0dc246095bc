// Scene builder: each solid against its formula, rotation, volume, no holes,
// composition, the standard scene's statistics, bad input.
#include "ris/scene/scene_builder.h"
#include "build_paths.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "ris/scene/scene_stats.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

// A scene from TOML text: a 1 m grid of n x n cells plus the objects given.
Scene build_text(const std::string& text) {
  const toml::table doc = toml::parse(text);
  return build_scene(parse_scene_description(doc, "test.toml"));
}

std::string grid(int n, double cell_m = 1.0, double base_m = 0.0) {
  return "[grid]\nrows = " + std::to_string(n) + "\ncols = " + std::to_string(n) +
         "\ncell_size = " + std::to_string(cell_m) +
         "\nbase_elevation = " + std::to_string(base_m) + "\nbase_category = 0\n";
}

// Elevation (metres above the base) of the cell whose centre is (x, y).
double h_at(const Scene& s, double x_m, double y_m, double base_m = 0.0) {
  const int col = static_cast<int>(std::floor(x_m / s.dx_m));
  const int row = s.rows - 1 - static_cast<int>(std::floor(y_m / s.dy_m));
  EXPECT_TRUE(s.contains(row, col)) << x_m << "," << y_m;
  return s.elevation_m[s.index(row, col)] - base_m;
}
std::uint16_t cat_at(const Scene& s, double x_m, double y_m) {
  const int col = static_cast<int>(std::floor(x_m / s.dx_m));
  const int row = s.rows - 1 - static_cast<int>(std::floor(y_m / s.dy_m));
  return s.category[s.index(row, col)];
}

// float32 elevations of tens of metres: 1e-4 m is far above rounding.
constexpr double kTolM = 1e-4;

TEST(SceneBuilder, PyramidApexAndMidFace) {
  // Base 101 m from (20, 20): apex at (70.5, 70.5), a cell centre.
  const Scene s = build_text(grid(200) + R"(
[[object]]
type = "pyramid"
x = 20
y = 20
base = 101
height = 50
category = 4
)");
  EXPECT_NEAR(h_at(s, 70.5, 70.5), 50.0, kTolM);
  // Mid-face of each face: 25 m from the apex towards each side.
  const double a = 50.5;
  const double expected = 50.0 * (1.0 - 25.0 / a);
  EXPECT_NEAR(h_at(s, 70.5, 45.5), expected, kTolM);  // south face
  EXPECT_NEAR(h_at(s, 70.5, 95.5), expected, kTolM);  // north face
  EXPECT_NEAR(h_at(s, 45.5, 70.5), expected, kTolM);  // west face
  EXPECT_NEAR(h_at(s, 95.5, 70.5), expected, kTolM);  // east face
  EXPECT_EQ(cat_at(s, 70.5, 45.5), 4);
  EXPECT_NEAR(h_at(s, 19.5, 70.5), 0.0, kTolM);  // outside
  EXPECT_EQ(cat_at(s, 19.5, 70.5), 0);
}

TEST(SceneBuilder, HemisphereCentreAndHalfRadius) {
  const Scene s = build_text(grid(200) + R"(
[[object]]
type = "hemisphere"
x = 100.5
y = 100.5
radius = 40
category = 8
)");
  EXPECT_NEAR(h_at(s, 100.5, 100.5), 40.0, kTolM);
  // r/2 from the centre: sqrt(r^2 - r^2/4) = r sqrt(3)/2.
  EXPECT_NEAR(h_at(s, 120.5, 100.5), 40.0 * std::sqrt(3.0) / 2.0, kTolM);
  EXPECT_NEAR(h_at(s, 100.5, 80.5), 40.0 * std::sqrt(3.0) / 2.0, kTolM);
  EXPECT_NEAR(h_at(s, 141.5, 100.5), 0.0, kTolM);
  EXPECT_EQ(cat_at(s, 141.5, 100.5), 0);
}

TEST(SceneBuilder, WedgeEveryFace) {
  const Scene s = build_text(grid(200) + R"(
[[object]]
type = "wedge"
x = 20
y = 20
length = 100
height = 30
front_slope = 30
top_width = 20
back_slope = 60
category = 3
)");
  const double t30 = std::tan(deg_to_rad(30.0));
  const double t60 = std::tan(deg_to_rad(60.0));
  const double v1 = 30.0 / t30, v2 = v1 + 20.0, v3 = v2 + 30.0 / t60;
  EXPECT_NEAR(h_at(s, 50.5, 20.0 + 25.5), 25.5 * t30, kTolM);                // front face
  EXPECT_NEAR(h_at(s, 50.5, 20.0 + 60.5), 30.0, kTolM);                      // flat top
  EXPECT_NEAR(h_at(s, 50.5, 20.0 + 80.5), 30.0 - (80.5 - v2) * t60, kTolM);  // back face
  EXPECT_NEAR(h_at(s, 50.5, 20.0 + std::ceil(v3) + 0.5), 0.0, kTolM);        // beyond the back toe
  EXPECT_NEAR(h_at(s, 120.5, 20.0 + 60.5), 0.0, kTolM);                      // beyond the length
  EXPECT_NEAR(h_at(s, 119.5, 20.0 + 60.5), 30.0, kTolM);                     // last cell of it
  EXPECT_EQ(cat_at(s, 50.5, 20.0 + 80.5), 3);
}

TEST(SceneBuilder, BoxCylinderTower) {
  const Scene s = build_text(grid(200) + R"(
[[object]]
type = "box"
x = 10
y = 10
length = 30
width = 20
height = 12
category = 5

[[object]]
type = "cylinder"
x = 20
y = 100.5
radius = 30
length = 100
category = 6

[[object]]
type = "tower"
x = 170.5
y = 170.5
radius = 10
height = 77
category = 7
)");
  EXPECT_NEAR(h_at(s, 10.5, 10.5), 12.0, kTolM);
  EXPECT_NEAR(h_at(s, 39.5, 29.5), 12.0, kTolM);
  EXPECT_NEAR(h_at(s, 40.5, 29.5), 0.0, kTolM);
  EXPECT_NEAR(h_at(s, 39.5, 30.5), 0.0, kTolM);
  // Cylinder: sqrt(r^2 - v^2) across the axis, constant along it.
  EXPECT_NEAR(h_at(s, 50.5, 100.5), 30.0, kTolM);
  EXPECT_NEAR(h_at(s, 50.5, 115.5), std::sqrt(900.0 - 225.0), kTolM);
  EXPECT_NEAR(h_at(s, 119.5, 85.5), std::sqrt(900.0 - 225.0), kTolM);
  EXPECT_NEAR(h_at(s, 120.5, 100.5), 0.0, kTolM);
  EXPECT_NEAR(h_at(s, 170.5, 170.5), 77.0, kTolM);
  EXPECT_NEAR(h_at(s, 180.5, 170.5), 77.0, kTolM);  // d = r: on the rim
  EXPECT_NEAR(h_at(s, 181.5, 170.5), 0.0, kTolM);
  EXPECT_EQ(cat_at(s, 180.5, 170.5), 7);
}

TEST(SceneBuilder, BaseElevationAndComposition) {
  // A tower through a hemisphere: the higher surface wins; the later object's
  // category wins where it stands, even where it is lower; a patch keeps the
  // relief and changes the category.
  const Scene s = build_text(grid(100, 1.0, 100.0) + R"(
[[object]]
type = "hemisphere"
x = 50.5
y = 50.5
radius = 30
category = 8

[[object]]
type = "tower"
x = 50.5
y = 50.5
radius = 5
height = 10
category = 7

[[object]]
type = "patch"
x = 70
y = 40
length = 20
width = 20
category = 2
)");
  EXPECT_NEAR(h_at(s, 50.5, 50.5, 100.0), 30.0, kTolM);  // hemisphere higher than tower
  EXPECT_EQ(cat_at(s, 50.5, 50.5), 7);                   // but the tower's category
  EXPECT_NEAR(h_at(s, 10.5, 10.5, 100.0), 0.0, kTolM);   // base plane at 100 m
  const double d = 75.5 - 50.5;
  EXPECT_NEAR(h_at(s, 75.5, 50.5, 100.0), std::sqrt(900.0 - d * d), kTolM);  // under the patch
  EXPECT_EQ(cat_at(s, 75.5, 50.5), 2);
  EXPECT_EQ(cat_at(s, 60.5, 50.5), 8);
}

TEST(SceneBuilder, CheckerboardCyclesCategories) {
  const Scene s = build_text(grid(40) + R"(
[[object]]
type = "checkerboard"
square = 10
categories = [1, 2, 3]
)");
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      EXPECT_EQ(cat_at(s, 10.0 * i + 5.0, 10.0 * j + 5.0), 1 + (i + j) % 3) << i << "," << j;
    }
  }
  EXPECT_EQ(scene_stats(s).max_elevation_m, 0.0);
}

// Rotation by +90 deg about an anchor at the centre of a square grid maps
// cell (row, col) of the unrotated scene A onto cell (N-1-col, row) of B:
// B[row][col] = A[col][N-1-row].
void expect_rotation_is_transpose(const std::string& object) {
  const int n = 120;
  const Scene a = build_text(grid(n) + "[[object]]\nrotation = 0\n" + object);
  const Scene b = build_text(grid(n) + "[[object]]\nrotation = 90\n" + object);
  int differ = 0;
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const std::size_t ib = b.index(row, col);
      const std::size_t ia = a.index(col, n - 1 - row);
      if (std::abs(b.elevation_m[ib] - a.elevation_m[ia]) > 1e-4 ||
          b.category[ib] != a.category[ia]) {
        ++differ;
      }
    }
  }
  EXPECT_EQ(differ, 0) << object;
  EXPECT_GT(scene_stats(a).category_counts.size(), 1u) << "object missing: " << object;
}

TEST(SceneBuilder, RotationBy90IsTheTransposedPlacement) {
  expect_rotation_is_transpose(
      "type = 'box'\nx = 60\ny = 60\nlength = 37\nwidth = 15\nheight = 9\ncategory = 5\n");
  expect_rotation_is_transpose(
      "type = 'wedge'\nx = 60\ny = 60\nlength = 40\nheight = 20\nfront_slope = 35\n"
      "top_width = 7\nback_slope = 55\ncategory = 3\n");
  expect_rotation_is_transpose(
      "type = 'pyramid'\nx = 60\ny = 60\nbase = 41\nheight = 30\ncategory = 4\n");
  expect_rotation_is_transpose(
      "type = 'cylinder'\nx = 60\ny = 60\nradius = 12.3\nlength = 45\ncategory = 6\n");
  expect_rotation_is_transpose(
      "type = 'patch'\nx = 60\ny = 60\nlength = 33\nwidth = 12\ncategory = 2\n");
  expect_rotation_is_transpose(
      "type = 'checkerboard'\nx = 60\ny = 60\nlength = 50\nwidth = 40\nsquare = 10\n"
      "categories = [1, 2, 3, 4]\n");
}

// Volume above the base plane, and the check that no cell whose centre is
// strictly inside the footprint was left at ground height.
struct SolidCase {
  std::string object;  // TOML of one object (rotation included)
  double volume_m3;    // analytic
  // Strictly inside the footprint (margin 1e-6 m), given the local point.
  std::function<bool(double, double)> inside;
};

void expect_volume_and_no_holes(const SolidCase& c) {
  const double cell = 0.25;
  const int n = 480;  // 120 m
  const Scene s = build_text(grid(n, cell) + "[[object]]\n" + c.object);
  double volume = 0.0;
  int holes = 0, inside = 0;
  for (int row = 0; row < n; ++row) {
    for (int col = 0; col < n; ++col) {
      const double z = s.elevation_m[s.index(row, col)];
      volume += z * cell * cell;
      const auto [x, y] = s.cell_centre(row, col);
      if (c.inside(x, y)) {
        ++inside;
        if (!(z > 0.0)) ++holes;
      }
    }
  }
  EXPECT_NEAR(volume, c.volume_m3, 0.01 * c.volume_m3) << c.object;
  EXPECT_GT(inside, 1000) << c.object;
  EXPECT_EQ(holes, 0) << c.object;
}

// Object frame of a point for anchor (x0, y0) and rotation a (degrees).
std::pair<double, double> uv(double x, double y, double x0, double y0, double a_deg) {
  const double a = deg_to_rad(a_deg);
  const double dx = x - x0, dy = y - y0;
  return {std::cos(a) * dx + std::sin(a) * dy, -std::sin(a) * dx + std::cos(a) * dy};
}

TEST(SceneBuilder, VolumesWithinOnePercentAndNoHoles) {
  constexpr double e = 1e-6;
  const double pi = kPi;
  std::vector<SolidCase> cases;
  cases.push_back(
      {"type = 'box'\nx = 40\ny = 20\nlength = 50\nwidth = 30\nheight = 10\n"
       "rotation = 37\ncategory = 5\n",
       50.0 * 30.0 * 10.0, [=](double x, double y) {
         auto [u, v] = uv(x, y, 40, 20, 37);
         return u > e && u < 50 - e && v > e && v < 30 - e;
       }});
  {
    const double h = 20, tf = std::tan(deg_to_rad(25.0)), tb = std::tan(deg_to_rad(50.0));
    const double v1 = h / tf, v2 = v1 + 8.0, v3 = v2 + h / tb;
    cases.push_back(
        {"type = 'wedge'\nx = 30\ny = 15\nlength = 40\nheight = 20\nfront_slope = 25\n"
         "top_width = 8\nback_slope = 50\nrotation = 23\ncategory = 3\n",
         40.0 * h * (v1 / 2.0 + 8.0 + (v3 - v2) / 2.0), [=](double x, double y) {
           auto [u, v] = uv(x, y, 30, 15, 23);
           return u > e && u < 40 - e && v > e && v < v3 - e;
         }});
  }
  cases.push_back(
      {"type = 'pyramid'\nx = 50\ny = 20\nbase = 60\nheight = 40\n"
       "rotation = 41\ncategory = 4\n",
       60.0 * 60.0 * 40.0 / 3.0, [=](double x, double y) {
         auto [u, v] = uv(x, y, 50, 20, 41);
         return u > e && u < 60 - e && v > e && v < 60 - e;
       }});
  cases.push_back({"type = 'hemisphere'\nx = 60.1\ny = 59.7\nradius = 30\ncategory = 8\n",
                   2.0 / 3.0 * pi * 30.0 * 30.0 * 30.0,
                   [=](double x, double y) { return std::hypot(x - 60.1, y - 59.7) < 30 - e; }});
  cases.push_back(
      {"type = 'cylinder'\nx = 20\ny = 30\nradius = 15\nlength = 70\n"
       "rotation = 33\ncategory = 6\n",
       pi * 15.0 * 15.0 * 70.0 / 2.0, [=](double x, double y) {
         auto [u, v] = uv(x, y, 20, 30, 33);
         return u > e && u < 70 - e && std::abs(v) < 15 - e;
       }});
  cases.push_back({"type = 'tower'\nx = 60.3\ny = 60.2\nradius = 20\nheight = 35\ncategory = 7\n",
                   pi * 20.0 * 20.0 * 35.0,
                   [=](double x, double y) { return std::hypot(x - 60.3, y - 60.2) < 20 - e; }});
  for (const SolidCase& c : cases) expect_volume_and_no_holes(c);
}

TEST(SceneBuilder, ObjectsAreClippedAtTheBorder) {
  // A pyramid hanging over the south-west corner: the part inside is exact.
  const Scene s = build_text(grid(50) + R"(
[[object]]
type = "pyramid"
x = -30
y = -30
base = 61
height = 20
category = 4
)");
  EXPECT_NEAR(h_at(s, 0.5, 0.5), 20.0, kTolM);
  EXPECT_NEAR(h_at(s, 10.5, 0.5), 20.0 * (1.0 - 10.0 / 30.5), kTolM);
  EXPECT_NEAR(h_at(s, 31.5, 0.5), 0.0, kTolM);
}

TEST(SceneBuilder, StandardSceneHasTheSeedsSizeApexAndTenCategories) {
  const SceneDescription d =
      read_scene_description(std::string(ris::test::data_dir()) + "/scenes/ku-geometric.toml");
  EXPECT_EQ(d.name, "ku-geometric");
  EXPECT_EQ(d.category_names.size(), 10u);
  EXPECT_EQ(d.category_names.at(1), "wheat stubble");
  EXPECT_EQ(d.category_names.at(10), "green wheat");
  const Scene s = build_scene(d);
  EXPECT_EQ(s.cols, 1000);
  EXPECT_EQ(s.rows, 700);
  EXPECT_NEAR(s.dx_m, 20.0 * kFeetToMetres, 1e-12);
  const SceneStats st = scene_stats(s);
  EXPECT_EQ(st.nodata_cells, 0u);
  EXPECT_EQ(st.valid_cells, 700000u);
  // The 2000 ft pyramid's apex sits on a cell centre.
  EXPECT_NEAR(st.max_elevation_m, 2000.0 * kFeetToMetres, 1e-3);
  EXPECT_EQ(st.min_elevation_m, 0.0);
  // Every one of the ten categories is used and the counts cover the grid.
  // The exact count of each was read off the built scene, not derived
  // independently: it is pinned as golden data (tests/golden/streamed-blocks,
  // scene.tif band 2's value_counts; docs/testing.md), not here.
  ASSERT_EQ(st.category_counts.size(), 10u);
  std::size_t total = 0;
  for (const auto& [category, n] : st.category_counts) {
    EXPECT_GE(category, 1);
    EXPECT_LE(category, 10);
    EXPECT_GT(n, 0u) << "category " << category;
    total += n;
  }
  EXPECT_EQ(total, 700000u);
}

// Bad input: each an InputError naming the file and the key.
void expect_input_error(const std::string& text, const std::string& key,
                        const std::string& what_part) {
  try {
    build_text(text);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "test.toml");
    EXPECT_EQ(e.key(), key) << e.what();
    EXPECT_THAT(e.what(), ::testing::HasSubstr(what_part));
  }
}

// Enum values without regard to case, as a radar's (issue 38): an object's
// type too; a misspelt one is named with the nearest.
TEST(SceneBuilder, ObjectTypesIgnoreCaseAndSuggest) {
  const std::string g = grid(50);
  const std::string box = "x = 10\ny = 10\nlength = 8\nwidth = 8\nheight = 3\ncategory = 2\n";
  const Scene lower = build_text(g + "[[object]]\ntype = 'box'\n" + box);
  const Scene mixed = build_text(g + "[[object]]\ntype = 'Box'\n" + box);
  EXPECT_EQ(lower.elevation_m, mixed.elevation_m);
  EXPECT_EQ(lower.category, mixed.category);
  expect_input_error(g + "[[object]]\ntype = 'boxx'\n" + box, "object[0].type",
                     "unknown object type \"boxx\" (did you mean \"box\"?)");
}

TEST(SceneBuilder, BadInputNamesFileAndKey) {
  const std::string g = grid(50);
  expect_input_error(g + "[[object]]\ntype = 'cone'\n", "object[0].type", "unknown object type");
  expect_input_error(g + "[[object]]\ntype = 'tower'\nx = 1\ny = 1\nradius = 2\nheight = 3\n"
                         "category = 1\ncolour = 'red'\n",
                     "", "object[0].colour");
  expect_input_error(g + "[[object]]\ntype = 'tower'\nx = 1\ny = 1\nradius = 2\ncategory = 1\n",
                     "object[0].height", "missing");
  expect_input_error(g + "[[object]]\ntype = 'box'\nx = 1\ny = 1\nlength = 0\nwidth = 2\n"
                         "height = 3\ncategory = 1\n",
                     "object[0].length", "> 0");
  expect_input_error(g + "[[object]]\ntype = 'hemisphere'\nx = 1\ny = 1\nradius = '-2 ft'\n"
                         "category = 1\n",
                     "object[0].radius", "> 0");
  expect_input_error(g + "[[object]]\ntype = 'wedge'\nx = 1\ny = 1\nlength = 5\nheight = 3\n"
                         "front_slope = 90\ntop_width = 1\nback_slope = 30\ncategory = 1\n",
                     "object[0].front_slope", "strictly between 0 and 90");
  expect_input_error(g + "[[object]]\ntype = 'wedge'\nx = 1\ny = 1\nlength = 5\nheight = 3\n"
                         "front_slope = 30\ntop_width = 1\nback_slope = 95\ncategory = 1\n",
                     "object[0].back_slope", "strictly between 0 and 90");
  expect_input_error(g + "[[object]]\ntype = 'patch'\nx = 1\ny = 1\nlength = 5\nwidth = 3\n"
                         "category = 70000\n",
                     "object[0].category", "out of range");
  expect_input_error(g + "[[object]]\ntype = 'checkerboard'\nsquare = 5\ncategories = [1, -2]\n",
                     "object[0].categories", "out of range");
  expect_input_error(g + "[[object]]\ntype = 'patch'\nx = '1 furlong'\ny = 1\nlength = 5\n"
                         "width = 3\ncategory = 1\n",
                     "object[0].x", "");
  expect_input_error("[grid]\nrows = 10\ncols = 10\n", "grid.cell_size", "missing");
  expect_input_error("[grid]\nrows = 0\ncols = 10\ncell_size = 1\n", "grid.rows", "between 1");
  expect_input_error("[grid]\nrows = 10\ncols = 10\ncell_size = 1\nbase_category = 65535\n",
                     "grid.base_category", "out of range");
  expect_input_error("[grid]\nrows = 10\ncols = 10\ncell_size = 1\ncrs = 'EPSG:nonsense'\n",
                     "grid.crs", "coordinate reference system");
  expect_input_error("[grid]\nrows = 1000000\ncols = 1000000\ncell_size = 1\n", "grid", "GiB");
  expect_input_error("[grids]\nrows = 10\n", "grid", "missing required table");
}

TEST(SceneBuilder, ObjectWhollyOutsideIsAWarningNotAnError) {
  const Scene s = build_text(grid(20) + R"(
[[object]]
type = "tower"
x = 500
y = 500
radius = 3
height = 10
category = 7
)");
  EXPECT_EQ(scene_stats(s).max_elevation_m, 0.0);
  EXPECT_EQ(scene_stats(s).category_counts.at(0), 400u);
}

TEST(SceneBuilder, OriginAndCrs) {
  const Scene s = build_text(
      "[grid]\nrows = 10\ncols = 20\ncell_size = '20 ft'\norigin = [500000, 4200000]\n"
      "crs = 'EPSG:32614'\n");
  EXPECT_DOUBLE_EQ(s.origin_x_m, 500000.0);
  EXPECT_DOUBLE_EQ(s.origin_y_m, 4200000.0 + 10 * 6.096);
  EXPECT_THAT(s.crs_wkt, ::testing::HasSubstr("32614"));
}

}  // namespace
}  // namespace ris
