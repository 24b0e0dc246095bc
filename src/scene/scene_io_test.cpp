#include "ris/scene/scene_io.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ris/io/raster_io.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

Scene small_scene() {
  Scene s = Scene::flat(5, 7, 6.096, 10.0f, 3);
  s.origin_x_m = 500000.0;
  s.origin_y_m = 4200000.0;
  for (size_t i = 0; i < s.size(); ++i) {
    s.elevation_m[i] = 10.0f + 0.25f * static_cast<float>(i);
    s.category[i] = static_cast<std::uint16_t>(i % 11);
  }
  s.valid[4] = 0;
  s.category[4] = kNoDataCategory;
  return s;
}

TEST(SceneIo, GeoTiffRoundTripIsLossless) {
  test::TempDir dir;
  Scene s = small_scene();
  write_scene_geotiff(s, dir / "scene.tif");
  Scene r = read_scene(dir / "scene.tif");
  ASSERT_EQ(r.rows, s.rows);
  ASSERT_EQ(r.cols, s.cols);
  EXPECT_DOUBLE_EQ(r.dx_m, s.dx_m);
  EXPECT_DOUBLE_EQ(r.dy_m, s.dy_m);
  EXPECT_DOUBLE_EQ(r.origin_x_m, s.origin_x_m);
  EXPECT_DOUBLE_EQ(r.origin_y_m, s.origin_y_m);
  for (size_t i = 0; i < s.size(); ++i) {
    EXPECT_EQ(r.valid[i], s.valid[i]) << i;
    EXPECT_EQ(r.category[i], s.category[i]) << i;
    if (s.valid[i]) {
      EXPECT_EQ(r.elevation_m[i], s.elevation_m[i]) << i;
    }
  }
  EXPECT_EQ(count_nodata(r), 1u);
}

TEST(SceneIo, ElevationOnlyRasterWithCategoryRaster) {
  test::TempDir dir;
  Scene s = small_scene();
  Georef g{s.geotransform(), ""};
  write_geotiff<float>(dir / "dem.tif", s.elevation_m.data(), s.cols, s.rows, &g, -9999.0);
  std::vector<std::uint16_t> cats(s.size(), 4);
  write_geotiff<std::uint16_t>(dir / "cat.tif", cats.data(), s.cols, s.rows, &g);
  Scene r = read_scene(dir / "dem.tif", dir / "cat.tif");
  EXPECT_EQ(r.category[0], 4);
  EXPECT_EQ(r.elevation_m[3], s.elevation_m[3]);
  EXPECT_EQ(count_nodata(r), 0u);
}

TEST(SceneIo, CategoryRasterOnAnotherGridIsAnError) {
  test::TempDir dir;
  Scene s = small_scene();
  Georef g{s.geotransform(), ""};
  write_geotiff<float>(dir / "dem.tif", s.elevation_m.data(), s.cols, s.rows, &g);
  Georef shifted = g;
  shifted.geotransform[0] += 1.0;
  std::vector<std::uint16_t> cats(s.size(), 4);
  write_geotiff<std::uint16_t>(dir / "cat.tif", cats.data(), s.cols, s.rows, &shifted);
  try {
    read_scene(dir / "dem.tif", dir / "cat.tif");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cat.tif"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("grid"), std::string::npos);
  }
}

TEST(SceneIo, UnreadableAndNonRasterFilesAreErrors) {
  test::TempDir dir;
  EXPECT_THROW(read_scene(dir / "missing.tif"), InputError);
  test::write_file(dir / "text.tif", "this is not a raster\n");
  try {
    read_scene(dir / "text.tif");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("text.tif"), std::string::npos);
  }
}

TEST(SceneIo, NoPartialFileLeftOnFailure) {
  test::TempDir dir;
  Scene bad;  // empty: validate() throws before anything is written
  EXPECT_THROW(write_scene_geotiff(bad, dir / "bad.tif"), InputError);
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace ris
