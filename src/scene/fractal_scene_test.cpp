// write_fractal_scene: the streamed generator's file holds the noise field
// block for block, the spectral one fractal_terrain's scene, on the grid asked
// for; bad output is refused before any work.
#include "ris/scene/fractal_scene.h"

#include <gdal_priv.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ris/scene/fractal_noise.h"
#include "ris/scene/geo_frame.h"
#include "ris/scene/scene_io.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

FractalSceneRequest request(int rows, int cols) {
  FractalSceneRequest r;
  r.params.rows = rows;
  r.params.cols = cols;
  r.params.cell_m = 20.0;
  r.params.relief_m = 400.0;
  r.params.base_m = 50.0;
  r.params.seed = 11;
  r.params.category = 3;
  return r;
}

std::string metadata_item(const std::filesystem::path& path, const char* key) {
  GDALDataset* ds = GDALDataset::Open(path.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY);
  const char* v = ds != nullptr ? ds->GetMetadataItem(key) : nullptr;
  std::string out = v != nullptr ? v : "";
  GDALClose(ds);
  return out;
}

TEST(FractalScene, StreamedFileIsTheNoiseFieldInBlocksOfRows) {
  test::TempDir dir;
  // 600 rows: two full blocks of 256 and a short one.
  FractalSceneRequest r = request(600, 90);
  r.generator = FractalGenerator::noise;
  std::vector<int> progress;
  r.rows_done = [&progress](int rows) { progress.push_back(rows); };
  const FractalSceneWritten w = write_fractal_scene(dir / "s.tif", r);
  EXPECT_TRUE(w.streamed);
  EXPECT_EQ(progress, (std::vector<int>{256, 512, 600}));
  const Scene s = read_scene(dir / "s.tif");
  ASSERT_EQ(s.rows, 600);
  ASSERT_EQ(s.cols, 90);
  std::vector<float> z(std::size_t(600) * 90);
  std::vector<std::uint16_t> cat(z.size());
  FractalNoise(r.params).rows(0, 600, z.data(), cat.data());
  EXPECT_EQ(s.elevation_m, z);
  EXPECT_EQ(s.category, cat);
  EXPECT_NE(metadata_item(dir / "s.tif", "RIS_GENERATOR").find("streamed"), std::string::npos);
  EXPECT_EQ(metadata_item(dir / "s.tif", "RIS_FRACTAL_CATEGORIES"), "3");
}

TEST(FractalScene, SpectralFileIsFractalTerrainAndItsHurstEstimate) {
  test::TempDir dir;
  const FractalSceneRequest r = request(128, 128);
  EXPECT_FALSE(fractal_streams(r));  // automatic: it fits in memory
  const FractalSceneWritten w = write_fractal_scene(dir / "s.tif", r);
  EXPECT_FALSE(w.streamed);
  const Scene want = fractal_terrain(r.params);
  EXPECT_EQ(read_scene(dir / "s.tif").elevation_m, want.elevation_m);
  EXPECT_NEAR(w.hurst_estimate, estimate_hurst(want, 8, 16), 1e-12);
  EXPECT_NE(metadata_item(dir / "s.tif", "RIS_GENERATOR").find("spectral"), std::string::npos);
}

TEST(FractalScene, CentredGridLiesOnItsLatitudeAndLongitude) {
  FractalSceneRequest r = request(300, 200);
  r.centre_lat_lon_deg = {{46.5, 8.0}};
  const Scene g = fractal_grid(r);
  ASSERT_FALSE(g.crs_wkt.empty());
  const auto [x, y] = GeoFrame(g.crs_wkt, "test").scene_from_lonlat(8.0, 46.5);
  // The centre within one cell of the grid's middle, the origin on whole cells.
  EXPECT_NEAR(g.origin_x_m + 0.5 * g.cols * g.dx_m, x, g.dx_m);
  EXPECT_NEAR(g.origin_y_m - 0.5 * g.rows * g.dy_m, y, g.dy_m);
  EXPECT_DOUBLE_EQ(std::remainder(g.origin_x_m, 20.0), 0.0);
  // Without a centre: the local frame, south-west corner at (0, 0).
  const Scene local = fractal_grid(request(300, 200));
  EXPECT_TRUE(local.crs_wkt.empty());
  EXPECT_DOUBLE_EQ(local.origin_x_m, 0.0);
  EXPECT_DOUBLE_EQ(local.origin_y_m, 300 * 20.0);
}

TEST(FractalScene, BadRequestsAreRefusedBeforeAnyFileIsWritten) {
  test::TempDir dir;
  FractalSceneRequest r = request(100, 100);
  r.params.hurst = 1.5;
  EXPECT_THROW(write_fractal_scene(dir / "h.tif", r), InputError);
  r = request(100, 100);
  EXPECT_THROW(write_fractal_scene(dir / "no-such-folder" / "s.tif", r), InputError);
  r = request(1000000, 1000000);  // about 4 TB
  r.generator = FractalGenerator::noise;
  try {
    write_fractal_scene(dir / "big.tif", r);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "--size");
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

}  // namespace
}  // namespace ris
