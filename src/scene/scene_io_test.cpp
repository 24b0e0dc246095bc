#include "ris/scene/scene_io.h"

#include <gtest/gtest.h>

#include <gdal.h>

#include <cmath>
#include <filesystem>

#include "ris/io/gdal_util.h"
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

// The VRT form: the same scene back, categories as a UInt16 band with the
// reserved no-data id, elevation Float32 with NaN, sources relative to the
// VRT (the folder moved whole still opens), the scene's metadata on the VRT.
TEST(SceneIo, VrtFormHoldsCategoriesAsAnIntegerBand) {
  test::TempDir dir;
  const Scene s = small_scene();
  write_scene_geotiff(s, dir / "scene.vrt", {{"RIS_SCENE_NAME", "small"}});
  const auto files = scene_files(dir / "scene.vrt");
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(files[0].filename(), "scene_elevation.tif");
  EXPECT_EQ(files[1].filename(), "scene_category.tif");
  for (const auto& f : files) EXPECT_TRUE(std::filesystem::is_regular_file(f)) << f;
  // Only the three files: no temporaries left.
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++n;
  EXPECT_EQ(n, 3);

  std::filesystem::create_directory(dir / "moved");
  for (const auto& f : files) std::filesystem::rename(f, dir / "moved" / f.filename());
  const std::filesystem::path vrt = dir / "moved" / "scene.vrt";
  GdalDataset ds = open_raster(vrt.string());
  ASSERT_EQ(GDALGetRasterCount(handle(ds)), 2);
  GDALRasterBandH z = GDALGetRasterBand(handle(ds), 1);
  GDALRasterBandH c = GDALGetRasterBand(handle(ds), 2);
  EXPECT_EQ(GDALGetRasterDataType(z), GDT_Float32);
  EXPECT_EQ(GDALGetRasterDataType(c), GDT_UInt16);
  int has = 0;
  EXPECT_EQ(GDALGetRasterNoDataValue(c, &has), 65535.0);
  EXPECT_TRUE(has);
  EXPECT_TRUE(std::isnan(GDALGetRasterNoDataValue(z, &has)));
  EXPECT_TRUE(has);
  EXPECT_STREQ(GDALGetDescription(c), "category");
  EXPECT_STREQ(GDALGetMetadataItem(handle(ds), "RIS_SCENE", nullptr), "1");
  EXPECT_STREQ(GDALGetMetadataItem(handle(ds), "RIS_SCENE_NAME", nullptr), "small");
  ds.reset();

  const Scene r = read_scene(vrt);
  const Scene t = [&] {
    write_scene_geotiff(s, dir / "scene.tif");
    return read_scene(dir / "scene.tif");
  }();
  ASSERT_EQ(r.rows, s.rows);
  ASSERT_EQ(r.cols, s.cols);
  EXPECT_DOUBLE_EQ(r.origin_x_m, s.origin_x_m);
  EXPECT_DOUBLE_EQ(r.origin_y_m, s.origin_y_m);
  EXPECT_EQ(r.valid, t.valid);
  EXPECT_EQ(r.category, t.category);
  EXPECT_EQ(r.elevation_m, t.elevation_m);
  EXPECT_EQ(r.category[4], kNoDataCategory);
  EXPECT_EQ(r.valid[4], 0);
}

TEST(SceneIo, VrtFormLeavesNothingOnFailure) {
  test::TempDir dir;
  const Scene s = small_scene();
  {
    SceneGeoTiffWriter out(dir / "scene.vrt", s);
    // Destroyed before close(): as a run that failed half way.
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
  EXPECT_FALSE(scene_is_vrt(dir / "scene.tif"));
  EXPECT_TRUE(scene_is_vrt(dir / "scene.VRT"));
}

}  // namespace
}  // namespace ris
