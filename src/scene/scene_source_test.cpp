// load_scene_source: descriptions are built, rasters read, labels carried.
#include "ris/scene/scene_source.h"

#include <gtest/gtest.h>

#include "ris/io/raster_io.h"
#include "ris/scene/scene_io.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

TEST(SceneSource, DescriptionIsBuiltWithItsLabels) {
  test::TempDir dir;
  test::write_file(dir / "s.TOML",
                   "name = 'tiny'\n[grid]\nrows = 4\ncols = 5\ncell_size = 2\nbase_category = 3\n"
                   "[category_names]\n3 = 'short alfalfa'\n");
  const LoadedScene in = load_scene_source((dir / "s.TOML").string());
  EXPECT_EQ(in.scene.cols, 5);
  EXPECT_EQ(in.name, "tiny");
  EXPECT_EQ(in.category_names.at(3), "short alfalfa");
  EXPECT_THROW(load_scene_source((dir / "s.TOML").string(), "cats.tif"), InputError);
}

TEST(SceneSource, RasterLabelsComeFromItsMetadata) {
  test::TempDir dir;
  const std::vector<float> z(6, 1.0f), cat(6, 3.0f);
  Georef g{{0, 2, 0, 6, 0, -2}, ""};
  RasterMetadata md = scene_label_metadata("tiny", {{3, "short alfalfa"}, {10, "green wheat"}});
  md["RIS_SCENE"] = "1";
  write_geotiff_bands<float>(dir / "s.tif", {{z.data(), "elevation_m"}, {cat.data(), "category"}},
                             3, 2, &g, std::nullopt, md);
  const LoadedScene in = load_scene_source((dir / "s.tif").string());
  EXPECT_EQ(in.scene.category[0], 3);
  EXPECT_EQ(in.name, "tiny");
  ASSERT_EQ(in.category_names.size(), 2u);
  EXPECT_EQ(in.category_names.at(10), "green wheat");
  // Without the items: no labels, no error.
  write_geotiff<float>(dir / "dem.tif", z.data(), 3, 2, &g);
  const LoadedScene dem = load_scene_source((dir / "dem.tif").string());
  EXPECT_TRUE(dem.name.empty());
  EXPECT_TRUE(dem.category_names.empty());
}

}  // namespace
}  // namespace ris
