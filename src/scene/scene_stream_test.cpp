#include "ris/scene/scene_stream.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "ris/io/raster_io.h"
#include "ris/scene/scene_io.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

Scene test_scene() {
  Scene s = Scene::flat(300, 270, 5.0, 10.0f, 2);
  s.origin_x_m = 1000.0;
  s.origin_y_m = 9000.0;
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      s.elevation_m[s.index(r, c)] = static_cast<float>(r) * 0.5f - static_cast<float>(c) * 0.25f;
      s.category[s.index(r, c)] = static_cast<std::uint16_t>((r / 30 + c / 40) % 5);
    }
  for (int r = 100; r < 140; ++r)
    for (int c = 7; c < 60; ++c) {
      s.valid[s.index(r, c)] = 0;
      s.category[s.index(r, c)] = kNoDataCategory;
    }
  return s;
}

// Any window equals the same cells of the whole scene read at once, and the
// grid comes from the header alone.
TEST(SceneStreamReader, WindowsEqualTheWholeScene) {
  const Scene s = test_scene();
  test::TempDir dir;
  write_scene_geotiff(s, dir / "s.tif");
  const Scene whole = read_scene(dir / "s.tif");
  for (std::size_t i = 0; i < s.size(); ++i)
    if (s.valid[i]) {
      ASSERT_EQ(whole.elevation_m[i], s.elevation_m[i]);
    }
  EXPECT_EQ(whole.category, s.category);
  EXPECT_EQ(whole.valid, s.valid);
  const SceneStreamReader in(dir / "s.tif");
  EXPECT_EQ(in.grid().rows, 300);
  EXPECT_EQ(in.grid().cols, 270);
  EXPECT_EQ(in.grid().dx_m, 5.0);
  EXPECT_EQ(in.grid().origin_y_m, 9000.0);
  EXPECT_TRUE(in.grid().elevation_m.empty());
  EXPECT_TRUE(in.has_categories());
  EXPECT_EQ(in.block_rows(), 256);  // tiled
  for (const auto& [r0, rows, c0, cols] :
       std::vector<std::array<int, 4>>{{0, 300, 0, 270}, {95, 50, 3, 61}, {299, 1, 269, 1}}) {
    const std::size_t n = static_cast<std::size_t>(rows) * cols;
    std::vector<float> z(n);
    std::vector<std::uint16_t> cat(n);
    std::vector<std::uint8_t> ok(n);
    in.read(r0, rows, c0, cols, z.data(), cat.data(), ok.data());
    for (int r = 0; r < rows; ++r)
      for (int c = 0; c < cols; ++c) {
        const std::size_t i = static_cast<std::size_t>(r) * cols + c;
        const std::size_t j = s.index(r0 + r, c0 + c);
        ASSERT_EQ(ok[i], s.valid[j]);
        ASSERT_EQ(cat[i], s.category[j]);
        if (ok[i]) {
          ASSERT_EQ(z[i], s.elevation_m[j]);
        }
      }
  }
}

TEST(SceneStreamReader, BadCategoryNamesItsCell) {
  test::TempDir dir;
  std::vector<float> z(20 * 10, 1.0f), cat(20 * 10, 1.0f);
  cat[7 * 10 + 3] = 2.5f;  // column 3, row 7
  const Georef g{{0, 1, 0, 20, 0, -1}, ""};
  write_geotiff_bands<float>(dir / "s.tif", {{z.data(), "elevation_m"}, {cat.data(), "category"}},
                             10, 20, &g, std::nullopt, {{"RIS_SCENE", "1"}});
  const SceneStreamReader in(dir / "s.tif");
  std::vector<float> zz(100);
  std::vector<std::uint16_t> cc(100);
  std::vector<std::uint8_t> ok(100);
  in.read(0, 5, 0, 10, zz.data(), cc.data(), ok.data());  // rows 0-4: fine
  try {
    in.read(5, 10, 0, 10, zz.data(), cc.data(), ok.data());
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("column 3, row 7"), std::string::npos) << e.what();
  }
  EXPECT_THROW(SceneStreamReader(dir / "missing.tif"), InputError);
}

}  // namespace
}  // namespace ris
