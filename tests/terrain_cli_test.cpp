// End-to-end runs of `ris scene import` and `ris scene fractal`.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

#include "build_paths.h"
#include "ris/io/raster_io.h"
#include "test_util.h"

namespace ris {
namespace {

const std::string kDem = std::string(ris::test::test_data_dir()) + "/dem/";

std::size_t nan_count(const RasterF64& r, int band) {
  std::size_t n = 0;
  const std::size_t cells = static_cast<std::size_t>(r.cols) * r.rows;
  for (std::size_t i = 0; i < cells; ++i) n += std::isnan(r.data[band * cells + i]);
  return n;
}

TEST(SceneImportCli, GeographicDemBecomesAUtmSceneWithItsNoDataCounted) {
  test::TempDir dir;
  const auto out = dir / "winnipeg.tif";
  auto r = test::run_ris("scene import " + kDem + "winnipeg_dem.tif -o " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("UTM zone 14N"), std::string::npos) << r.output;
  RasterF64 scene = read_raster_f64(out);
  EXPECT_EQ(scene.bands, 2);
  EXPECT_DOUBLE_EQ(scene.georef.geotransform[1], 25.0);
  EXPECT_NE(scene.metadata.at("RIS_FRAME").find("UTM zone 14N"), std::string::npos);
  EXPECT_EQ(scene.metadata.at("RIS_NODATA_CELLS"), std::to_string(nan_count(scene, 0)));
  EXPECT_GT(nan_count(scene, 0), 0u);

  auto coarse =
      test::run_ris("scene import " + kDem + "winnipeg_dem.tif --cell-size \"0.1 km\" -o " +
                    (dir / "coarse.tif").string());
  ASSERT_EQ(coarse.exit_code, 0) << coarse.output;
  RasterF64 c = read_raster_f64(dir / "coarse.tif");
  EXPECT_DOUBLE_EQ(c.georef.geotransform[1], 100.0);
  EXPECT_NEAR(c.cols, scene.cols / 4.0, 1.0);
}

TEST(SceneImportCli, NoCrsRefusedWithoutPartialOutputThenAcceptedWithCrs) {
  test::TempDir dir;
  std::vector<float> h(30 * 20, 10.0f);
  Georef g{{12.0, 1.0 / 3600, 0, 42.0, 0, -1.0 / 3600}, ""};
  write_geotiff<float>(dir / "nocrs.tif", h.data(), 30, 20, &g);
  const auto out = dir / "scene.tif";
  auto r = test::run_ris("scene import " + (dir / "nocrs.tif").string() + " -o " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("--crs"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(out));
  r = test::run_ris("scene import " + (dir / "nocrs.tif").string() + " --crs EPSG:4326 -o " +
                    out.string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_TRUE(std::filesystem::exists(out));
}

TEST(SceneImportCli, LandCoverCodesAreMappedOrListed) {
  test::TempDir dir;
  test::write_file(dir / "lib.toml",
                   "[[category]]\nid = 1\nname = \"grass\"\n[[category]]\nid = 2\nname = "
                   "\"forest\"\n");
  test::write_file(dir / "map.toml",
                   "[mapping]\nlibrary = \"lib.toml\"\n[classes]\n10 = \"forest\"\n");
  // Land cover in lat/lon over the San Andreas DEM: code 10 west, 30 east.
  const int cols = 120, rows = 260;
  std::vector<std::uint16_t> codes(cols * rows);
  for (int i = 0; i < cols * rows; ++i) codes[i] = (i % cols) < 60 ? 10 : 30;
  Georef g{{-118.4402, 0.00025, 0, 34.2102, 0, -0.00028}, ""};
  g.crs_wkt =
      R"(GEOGCS["WGS 84",DATUM["WGS_1984",SPHEROID["WGS 84",6378137,298.257223563]],PRIMEM["Greenwich",0],UNIT["degree",0.0174532925199433],AUTHORITY["EPSG","4326"]])";
  write_geotiff<std::uint16_t>(dir / "lc.tif", codes.data(), cols, rows, &g);
  const std::string base = "scene import " + kDem + "SanAnd_dem.tif --landcover " +
                           (dir / "lc.tif").string() + " --mapping " + (dir / "map.toml").string();
  auto r = test::run_ris(base + " -o " + (dir / "a.tif").string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("30 ("), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "a.tif"));

  r = test::run_ris(base + " --default-category grass -o " + (dir / "b.tif").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  RasterF64 s = read_raster_f64(dir / "b.tif");
  const std::size_t cells = static_cast<std::size_t>(s.cols) * s.rows;
  std::size_t grass = 0, forest = 0;
  for (std::size_t i = 0; i < cells; ++i) {
    grass += s.data[cells + i] == 1.0;
    forest += s.data[cells + i] == 2.0;
  }
  EXPECT_GT(grass, cells / 4);
  EXPECT_GT(forest, cells / 4);
  EXPECT_EQ(s.metadata.at("RIS_LANDCOVER"), "lc.tif");
}

TEST(SimulateTerrainCli, GeographicDemSimulatesDirectlyWithAGeographicTrackAndGeocodedProducts) {
  test::TempDir dir;
  test::write_file(dir / "radar.toml", R"(name = "t"
mode = "slar"
frequency = "9.4 GHz"
polarisation = "HH"
pulse_width = "0.2 us"
near_range = "10000 m"
far_range = "14000 m"
azimuth_beamwidth = "0.2 deg"
[track]
altitude = "3000 m"
start_latlon = [34.13, -118.55]
end_latlon = [34.22, -118.55]
)");
  const auto out = dir / "run";
  // Without land cover every cell is the default category (grass of the
  // generic library, kDefaultCategory), whose library ris then takes.
  auto r = test::run_ris("simulate --quiet --scene " + kDem + "SanAnd_dem.tif --radar " +
                         (dir / "radar.toml").string() + " --out " + (dir / "bare").string());
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("generic-terrain.toml, the library the scene names"), std::string::npos)
      << r.output;
  ASSERT_EQ(test::run_ris("scene import " + kDem + "SanAnd_dem.tif --category grass -o " +
                          (dir / "grass.tif").string())
                .exit_code,
            0);
  r = test::run_ris("simulate --scene " + (dir / "grass.tif").string() + " --radar " +
                    (dir / "radar.toml").string() + " --backscatter " + ris::test::data_dir() +
                    "/backscatter/generic-terrain.toml --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  RasterF64 geo = read_raster_f64(out / "geocoded_power.tif");
  RasterF64 scene = read_raster_f64(dir / "grass.tif");
  EXPECT_EQ(geo.cols, scene.cols);
  EXPECT_EQ(geo.georef.geotransform, scene.georef.geotransform);
  EXPECT_NE(geo.georef.crs_wkt.find("UTM zone 11N"), std::string::npos);
  // A cell with data has geocoded power exactly when the scene mask says it
  // was imaged (not outside the swath, 16); most of the DEM is. (No-data
  // cells, 4, take the power of the pixel their position maps to.)
  const RasterF64 mask = read_raster_f64(out / "scene_mask.tif");
  ASSERT_EQ(mask.data.size(), geo.data.size());
  std::size_t imaged = 0, disagree = 0;
  for (std::size_t i = 0; i < geo.data.size(); ++i) {
    const int bits = static_cast<int>(mask.data[i]);
    if (bits & 4) continue;
    const bool in = (bits & 16) == 0;
    imaged += in;
    disagree += in != std::isfinite(geo.data[i]);
  }
  EXPECT_EQ(disagree, 0u);
  EXPECT_GT(imaged, static_cast<std::size_t>(geo.cols * geo.rows) / 2);
  // The track in metadata also in latitude/longitude, back where it was given.
  const auto meta = nlohmann::json::parse(test::read_file(out / "metadata.json"));
  const auto& track = meta.at("derived").at("track");
  EXPECT_NEAR(track.at("start_latlon")[0].get<double>(), 34.13, 1e-9);
  EXPECT_NEAR(track.at("start_latlon")[1].get<double>(), -118.55, 1e-9);
  EXPECT_NEAR(track.at("end_latlon")[0].get<double>(), 34.22, 1e-6);
}

TEST(SceneFractalCli, SameSeedSameSceneAndReliefAsAsked) {
  test::TempDir dir;
  const std::string args =
      "scene fractal --size 96x64 --cell-size 10 --relief \"500 ft\" --hurst 0.6";
  ASSERT_EQ(test::run_ris(args + " --seed 4 -o " + (dir / "a.tif").string()).exit_code, 0);
  ASSERT_EQ(test::run_ris(args + " --seed 4 -o " + (dir / "b.tif").string()).exit_code, 0);
  ASSERT_EQ(test::run_ris(args + " --seed 5 -o " + (dir / "c.tif").string()).exit_code, 0);
  RasterF64 a = read_raster_f64(dir / "a.tif");
  RasterF64 b = read_raster_f64(dir / "b.tif");
  RasterF64 c = read_raster_f64(dir / "c.tif");
  EXPECT_EQ(a.data, b.data);
  EXPECT_NE(a.data, c.data);
  ASSERT_EQ(a.cols, 96);
  ASSERT_EQ(a.rows, 64);
  double lo = 1e9, hi = -1e9;
  for (int i = 0; i < 96 * 64; ++i) lo = std::min(lo, a.data[i]), hi = std::max(hi, a.data[i]);
  EXPECT_NEAR(lo, 0.0, 1e-3);
  EXPECT_NEAR(hi, 500 * 0.3048, 1e-3);

  auto placed = test::run_ris(args + " --centre 46.5,8.0 -o " + (dir / "d.tif").string());
  ASSERT_EQ(placed.exit_code, 0) << placed.output;
  RasterF64 d = read_raster_f64(dir / "d.tif");
  EXPECT_NE(d.georef.crs_wkt.find("UTM zone 32N"), std::string::npos);

  // Patches named from the generic terrain library, labelled in the file.
  ASSERT_EQ(test::run_ris(args + " --patches forest,grass --patch-size 200 -o " +
                          (dir / "p.tif").string())
                .exit_code,
            0);
  RasterF64 p = read_raster_f64(dir / "p.tif");
  EXPECT_NE(p.metadata.at("RIS_CATEGORY_NAMES").find("forest"), std::string::npos);

  auto bad = test::run_ris("scene fractal --hurst 1.5 -o " + (dir / "e.tif").string());
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("--hurst"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace ris
