// Scene pictures: palette, hillshade against the analytic cosine, the preview
// map's colours and contours, the PNG.
#include "ris/image/scene_preview.h"
#include "build_paths.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <tuple>

#include "ris/backscatter/library.h"
#include "ris/image/category_palette.h"
#include "ris/image/hillshade.h"
#include "ris/io/raster_io.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

TEST(CategoryPalette, CropsAreDistinctAndStable) {
  std::set<std::tuple<int, int, int>> seen;
  for (std::uint16_t id = 0; id <= 40; ++id) {
    const Rgb8 c = category_colour(id);
    seen.insert({c.r, c.g, c.b});
    const Rgb8 again = category_colour(id);
    EXPECT_EQ(c.r, again.r);
  }
  EXPECT_EQ(seen.size(), 41u);  // no two of the first 41 ids share a colour
}

TEST(CategoryPalette, MatchesTheShippedCategoryLibraries) {
  for (const char* lib : {"ku-geometric.toml", "generic-terrain.toml"}) {
    const auto src = load_sigma0_source(std::string(ris::test::data_dir()) + "/backscatter/" + lib);
    int checked = 0;
    for (std::uint16_t id = 0; id < 64; ++id) {
      if (!src->has_category(id)) continue;
      const auto lib_colour = src->category_colour(id);
      ASSERT_TRUE(lib_colour.has_value()) << lib << " " << id;
      const Rgb8 c = category_colour(id);
      EXPECT_EQ(c.r, (*lib_colour)[0]) << lib << " " << id;
      EXPECT_EQ(c.g, (*lib_colour)[1]) << lib << " " << id;
      EXPECT_EQ(c.b, (*lib_colour)[2]) << lib << " " << id;
      ++checked;
    }
    EXPECT_GE(checked, 8) << lib;
  }
}

TEST(Hillshade, TiltedPlaneMatchesTheAnalyticCosine) {
  // z = x tan(a): rising east; light from the west (270 deg) at 45 deg.
  Scene s = Scene::flat(20, 20, 2.0, 0.0f, 1);
  const double a = deg_to_rad(20.0);
  for (int r = 0; r < s.rows; ++r) {
    for (int c = 0; c < s.cols; ++c) {
      s.elevation_m[s.index(r, c)] = static_cast<float>(s.cell_centre(r, c).first * std::tan(a));
    }
  }
  const std::vector<float> shade = hillshade(s, 270.0, 45.0);
  // n = (-tan a, 0, 1)/|.|, l = (-cos 45, 0, sin 45): n.l = cos a (tan a + 1) / sqrt 2.
  const double expected = std::cos(a) * (std::tan(a) + 1.0) / std::sqrt(2.0);
  EXPECT_NEAR(shade[s.index(10, 10)], expected, 1e-5);
  EXPECT_NEAR(shade[s.index(0, 0)], expected, 1e-5);  // one-sided at the corner
  // Lit from the east the same slope faces away: cos = cos a (1 - tan a)/sqrt 2.
  EXPECT_NEAR(hillshade(s, 90.0, 45.0)[s.index(5, 5)],
              std::cos(a) * (1.0 - std::tan(a)) / std::sqrt(2.0), 1e-5);
}

TEST(ScenePreview, ContourIntervalIsOneTwoFive) {
  ScenePreviewOptions opt;
  EXPECT_DOUBLE_EQ(preview_contour_interval_m(opt, 0.0, 609.6), 100.0);
  EXPECT_DOUBLE_EQ(preview_contour_interval_m(opt, 0.0, 1000.0), 100.0);
  EXPECT_DOUBLE_EQ(preview_contour_interval_m(opt, 0.0, 1001.0), 200.0);
  EXPECT_DOUBLE_EQ(preview_contour_interval_m(opt, 100.0, 103.0), 0.5);
  EXPECT_DOUBLE_EQ(preview_contour_interval_m(opt, 5.0, 5.0), 0.0);
  opt.contour_interval_m = -1.0;
  EXPECT_DOUBLE_EQ(preview_contour_interval_m(opt, 0.0, 609.6), 0.0);
  opt.contour_interval_m = 25.0;
  EXPECT_DOUBLE_EQ(preview_contour_interval_m(opt, 0.0, 609.6), 25.0);
}

TEST(ScenePreview, FlatGroundKeepsItsColourAndContoursDarken) {
  // West half at 0 m (category 3), east half a 50 m plateau (category 9).
  Scene s = Scene::flat(10, 10, 1.0, 0.0f, 3);
  for (int r = 0; r < 10; ++r) {
    for (int c = 5; c < 10; ++c) {
      s.elevation_m[s.index(r, c)] = 50.0f;
      s.category[s.index(r, c)] = 9;
    }
  }
  s.valid[s.index(0, 0)] = 0;
  ScenePreviewOptions opt;
  opt.contour_interval_m = 20.0;
  const std::vector<std::uint8_t> rgb = shaded_category_rgb(s, opt);
  auto px = [&](int r, int c) {
    const std::size_t i = 3 * s.index(r, c);
    return Rgb8{rgb[i], rgb[i + 1], rgb[i + 2]};
  };
  const Rgb8 c3 = category_colour(3), c9 = category_colour(9);
  // Interior flat cells: exactly the category colour.
  EXPECT_EQ(px(5, 1).r, c3.r);
  EXPECT_EQ(px(5, 1).g, c3.g);
  EXPECT_EQ(px(5, 8).b, c9.b);
  EXPECT_EQ(px(0, 0).r, kNoDataColour.r);
  // The plateau's edge cell (col 5) crosses 20 and 40 m: darkened.
  EXPECT_LT(px(5, 5).r + px(5, 5).g + px(5, 5).b, (c9.r + c9.g + c9.b) / 2 + 10);
}

TEST(ScenePreview, WritesAPngWithTheMapsCellsAndALegendWithSwatchAndText) {
  test::TempDir dir;
  Scene s = Scene::flat(30, 50, 6.096, 0.0f, 1);
  s.category[s.index(3, 3)] = 7;
  ScenePreviewOptions opt;
  opt.title = "tiny";
  opt.category_names = {{1, "wheat stubble"}};
  write_scene_preview(s, dir / "p.png", opt);
  const RasterF64 png = read_raster_f64(dir / "p.png");
  // Small grids are enlarged by whole pixels to at least 400 px: 8 x 50 = 400.
  EXPECT_GE(png.cols, 400 + 300);
  EXPECT_GE(png.rows, 8 * 30);
  ASSERT_GE(png.bands, 3);
  const std::size_t plane = static_cast<std::size_t>(png.cols) * png.rows;
  const auto is = [&](std::size_t i, Rgb8 c) {
    return png.data[i] == c.r && png.data[plane + i] == c.g && png.data[2 * plane + i] == c.b;
  };
  // The map: the one cell of category 7 is an 8 x 8 block of its colour; the
  // legend (right of the map): category 1's swatch and dark text.
  const Rgb8 c1 = category_colour(1), c7 = category_colour(7);
  int c7_map = 0, c1_legend = 0, dark_legend = 0;
  for (int y = 0; y < png.rows; ++y) {
    for (int x = 0; x < png.cols; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * png.cols + x;
      if (x < 400) {
        c7_map += is(i, c7);
      } else {
        c1_legend += is(i, c1);
        dark_legend += png.data[i] + png.data[plane + i] + png.data[2 * plane + i] < 200;
      }
    }
  }
  EXPECT_EQ(c7_map, 64);
  EXPECT_GT(c1_legend, 20);
  EXPECT_GT(dark_legend, 50);
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir.path())) ++files;
  EXPECT_EQ(files, 1);  // the PNG and no temporary
}

}  // namespace
}  // namespace ris
