// End-to-end: `ris scene build | info | preview` through the real executable.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "build_paths.h"
#include "ris/io/raster_io.h"
#include "ris/scene/scene_builder.h"
#include "ris/scene/scene_io.h"
#include "test_util.h"

namespace ris {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

using test::q;

const std::string kGrid = "[grid]\nrows = 40\ncols = 60\ncell_size = '20 ft'\nbase_category = 1\n";

TEST(SceneCli, BuildWritesTheSceneTheBuilderMakes) {
  test::TempDir dir;
  test::write_file(dir / "s.toml", kGrid + R"(
[[object]]
type = "pyramid"
x = "200 ft"
y = "100 ft"
base = "400 ft"
height = "300 ft"
category = 4
)");
  const auto r = test::run_ris("scene build " + q(dir / "s.toml") + " -o " + q(dir / "s.tif"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const Scene read = read_scene(dir / "s.tif");
  const Scene built = build_scene_file((dir / "s.toml").string());
  ASSERT_EQ(read.size(), built.size());
  EXPECT_EQ(read.elevation_m, built.elevation_m);
  EXPECT_EQ(read.category, built.category);
  EXPECT_DOUBLE_EQ(read.dx_m, 6.096);
}

TEST(SceneCli, DefaultSceneBuildInfoPreview) {
  test::TempDir dir;
  auto r = test::run_ris("scene build -o " + q(dir / "ku.tif"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_ris("scene info " + q(dir / "ku.tif"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("size: 1000 columns x 700 rows"));
  EXPECT_THAT(r.output, HasSubstr("cell size: 6.096 x 6.096 m (20 x 20 ft)"));
  EXPECT_THAT(r.output, HasSubstr("CRS: none"));
  EXPECT_THAT(r.output, HasSubstr("(0 .. 2000 ft)"));
  EXPECT_THAT(r.output, HasSubstr("no-data cells: 0"));
  EXPECT_THAT(r.output, HasSubstr("categories: 10"));
  // The description's name and labels travel in the GeoTIFF's metadata.
  EXPECT_THAT(r.output, HasSubstr("(ku-geometric)"));
  EXPECT_THAT(r.output, HasSubstr("short milo"));
  r = test::run_ris("scene info");  // the description itself, with names
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("ku-geometric"));
  EXPECT_THAT(r.output, HasSubstr("tall soybeans"));
  r = test::run_ris("scene preview " + q(dir / "ku.tif") + " -o " + q(dir / "p.png"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const RasterF64 png = read_raster_f64(dir / "p.png");
  EXPECT_GE(png.cols, 1000);  // one pixel per cell plus the legend
  EXPECT_GE(png.rows, 700);
}

// A bad scene: non-zero exit, a message naming the file and the key, and no
// output file (nor any temporary) left in the folder. `command` is "build"
// or "preview".
void expect_refused(const std::string& toml, const std::string& key, const std::string& what = "",
                    const std::string& command = "build") {
  test::TempDir dir;
  test::write_file(dir / "bad.toml", toml);
  fs::create_directory(dir / "out");
  const std::string cmd = "scene " + command + " " + q(dir / "bad.toml") + " -o " +
                          q(dir / "out" / (command == "build" ? "s.tif" : "p.png"));
  const auto r = test::run_ris(cmd);
  EXPECT_NE(r.exit_code, 0) << cmd << "\n" << r.output;
  EXPECT_THAT(r.output, HasSubstr("bad.toml")) << r.output;
  EXPECT_THAT(r.output, HasSubstr(key)) << r.output;
  EXPECT_THAT(r.output, HasSubstr(what)) << r.output;
  EXPECT_TRUE(fs::is_empty(dir / "out")) << cmd;
}

TEST(SceneCli, BadInputIsRefusedWithoutOutput) {
  const std::string tower = "[[object]]\ntype = 'tower'\nx = 1\ny = 1\n";
  expect_refused(kGrid + "[[object]]\ntype = 'obelisk'\n", "object[0].type", "unknown object type");
  expect_refused(kGrid + tower + "radius = 2\nheight = 3\ncategory = 1\nhieght = 3\n",
                 "object[0].hieght", "unknown key");
  expect_refused(kGrid + tower + "radius = 2\ncategory = 1\n", "object[0].height", "missing");
  expect_refused(kGrid + tower + "radius = 0\nheight = 3\ncategory = 1\n", "object[0].radius",
                 "> 0");
  expect_refused(kGrid + tower + "radius = 2\nheight = -3\ncategory = 1\n", "object[0].height",
                 "> 0");
  expect_refused(kGrid +
                     "[[object]]\ntype = 'wedge'\nx = 1\ny = 1\nlength = 5\nheight = 3\n"
                     "front_slope = '90 deg'\ntop_width = 1\nback_slope = 30\ncategory = 1\n",
                 "object[0].front_slope", "between 0 and 90");
  expect_refused(kGrid + tower + "radius = 2\nheight = 3\ncategory = -1\n", "object[0].category",
                 "out of range");
  expect_refused("[grid]\nrows = 3000000\ncols = 3000000\ncell_size = 1\n", "grid", "GiB");
  expect_refused("[grid]\nrows = 10\ncols = 10\ncell_size = 1\n[[object]\n", "", "syntax error");
  expect_refused(kGrid + "[[object]]\ntype = 'obelisk'\n", "object[0].type", "unknown object type",
                 "preview");
}

TEST(SceneCli, ObjectWhollyOutsideWarnsAndBuilds) {
  test::TempDir dir;
  test::write_file(dir / "s.toml", kGrid + R"(
[[object]]
type = "tower"
x = "-5000 ft"
y = "100 ft"
radius = "50 ft"
height = "100 ft"
category = 7
)");
  const auto r = test::run_ris("scene build " + q(dir / "s.toml") + " -o " + q(dir / "s.tif"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("warn"));
  EXPECT_THAT(r.output, HasSubstr("object[0] (tower) lies wholly outside the grid"));
  EXPECT_TRUE(fs::exists(dir / "s.tif"));
}

TEST(SceneCli, UnreadableOrNonRasterFileIsAnError) {
  test::TempDir dir;
  test::write_file(dir / "notes.tif", "this is not a raster\n");
  auto r = test::run_ris("scene info " + q(dir / "notes.tif"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("notes.tif"));
  r = test::run_ris("scene info " + q(dir / "missing.toml"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("missing.toml"));
  r = test::run_ris("scene preview " + q(dir / "notes.tif") + " -o " + q(dir / "p.png"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_FALSE(fs::exists(dir / "p.png"));
}

TEST(SceneCli, ElevationRasterWithCategoryRaster) {
  test::TempDir dir;
  const int cols = 30, rows = 20;
  std::vector<float> dem(cols * rows, 5.0f);
  dem[7] = 25.0f;
  std::vector<std::uint16_t> cats(cols * rows, 3);
  const Georef g{{1000.0, 10.0, 0.0, 5000.0, 0.0, -10.0}, ""};
  write_geotiff<float>(dir / "dem.tif", dem.data(), cols, rows, &g);
  write_geotiff<std::uint16_t>(dir / "cat.tif", cats.data(), cols, rows, &g);
  const Georef other{{1000.0, 20.0, 0.0, 5000.0, 0.0, -20.0}, ""};
  write_geotiff<std::uint16_t>(dir / "cat20.tif", cats.data(), cols, rows, &other);

  auto r =
      test::run_ris("scene info " + q(dir / "dem.tif") + " --categories " + q(dir / "cat.tif"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("size: 30 columns x 20 rows"));
  EXPECT_THAT(r.output, HasSubstr("elevation: 5 .. 25 m"));
  EXPECT_THAT(r.output, HasSubstr("      3:       600"));
  // A category raster on another grid: refused, no picture.
  r = test::run_ris("scene preview " + q(dir / "dem.tif") + " --categories " +
                    q(dir / "cat20.tif") + " -o " + q(dir / "p.png"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("cat20.tif"));
  EXPECT_FALSE(fs::exists(dir / "p.png"));
  // `scene build` takes descriptions only.
  r = test::run_ris("scene build " + q(dir / "dem.tif") + " -o " + q(dir / "s.tif"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_THAT(r.output, HasSubstr("scene description"));
  EXPECT_FALSE(fs::exists(dir / "s.tif"));
}

// The VRT form (docs/scene-format.md): built, described and simulated as
// the GeoTIFF form is, with the same product pixels; categories are UInt16.
TEST(SceneCli, VrtSceneSimulatesAsTheGeoTiff) {
  test::TempDir dir;
  auto r = test::run_ris("scene build -o " + q(dir / "ku.vrt"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(fs::is_regular_file(dir / "ku_category.tif"));
  r = test::run_ris("scene build -o " + q(dir / "ku.tif"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_ris("scene info " + q(dir / "ku.vrt"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_THAT(r.output, HasSubstr("categories: 10"));
  EXPECT_THAT(r.output, HasSubstr("(ku-geometric)"));
  const RasterF64 cats = read_raster_f64(dir / "ku_category.tif");
  const Scene built = read_scene(dir / "ku.tif");
  ASSERT_EQ(cats.data.size(), built.size());
  for (std::size_t i = 0; i < built.size(); i += 997)
    EXPECT_EQ(cats.data[i], built.category[i]) << i;
  for (const char* form : {"ku.vrt", "ku.tif"}) {
    r = test::run_ris("simulate --scene " + q(dir / form) +
                      " --products mean_power_slant,mask_slant" + " --out " +
                      q(dir / (std::string(form) + ".out")));
    ASSERT_EQ(r.exit_code, 0) << r.output;
  }
  for (const char* product : {"mean_power_slant.tif", "mask_slant.tif"}) {
    const RasterF64 a = read_raster_f64(dir / "ku.vrt.out" / product);
    const RasterF64 b = read_raster_f64(dir / "ku.tif.out" / product);
    ASSERT_EQ(a.data.size(), b.data.size()) << product;
    EXPECT_EQ(std::memcmp(a.data.data(), b.data.data(), a.data.size() * sizeof(double)), 0)
        << product;
  }
}

TEST(SceneCli, ObjectsListsEveryType) {
  const auto r = test::run_ris("scene objects");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* t :
       {"patch", "box", "wedge", "pyramid", "hemisphere", "cylinder", "tower", "checkerboard"}) {
    EXPECT_THAT(r.output, HasSubstr(t));
  }
}

TEST(SceneCli, TheDocumentedExampleBuilds) {
  // The indented block under "## Example" in docs/scene-format.md.
  const std::string doc =
      test::read_file(fs::path(ris::test::data_dir()).parent_path() / "docs" / "scene-format.md");
  const std::size_t start = doc.find("## Example");
  ASSERT_NE(start, std::string::npos);
  const std::size_t end = doc.find("\n## ", start + 1);
  std::string toml;
  std::istringstream lines(doc.substr(start, end - start));
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("    ", 0) == 0) toml += line.substr(4) + "\n";
  }
  ASSERT_THAT(toml, HasSubstr("type = \"pyramid\""));
  test::TempDir dir;
  test::write_file(dir / "example.toml", toml);
  const auto r = test::run_ris("scene info " + q(dir / "example.toml"));
  ASSERT_EQ(r.exit_code, 0) << r.output << toml;
  EXPECT_THAT(r.output, HasSubstr("size: 300 columns x 200 rows"));
  EXPECT_THAT(r.output, HasSubstr("short corn"));
}

}  // namespace
}  // namespace ris
