// End-to-end runs of `ris sensor optical|thermal` (docs/sensors.md).
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "build_paths.h"
#include "ris/io/raster_io.h"
#include "test_util.h"

namespace ris {
namespace {

using test::read_file;
using test::run_ris;
using test::run_ris_env;
using test::TempDir;
using test::write_file;

const char* kScene = R"(name = "eo-cli"
[grid]
rows = 60
cols = 80
cell_size = 5.0
base_category = 21
origin = [690000, 5330000]
crs = "EPSG:32632"
[[object]]
type = "pyramid"
x = 200
y = 150
base = 100
height = 60
category = 26
)";

std::string sensor_text(const std::string& kind, const std::string& bands,
                        const std::string& time) {
  return "kind = \"" + kind + "\"\ndate = \"2024-06-21\"\ntime = \"" + time +
         "\"\nbands = " + bands + "\nnoise = 0.3\n";
}

std::string table() {
  return std::string(test::data_dir()) + "/sensors_eo/generic-terrain-eo.csv";
}

TEST(SensorCli, OpticalProductsOverlayTheSceneGrid) {
  TempDir d;
  write_file(d.path() / "s.toml", kScene);
  write_file(d.path() / "o.toml",
             sensor_text("optical", "[\"blue\", \"green\", \"red\", \"nir\"]", "17:30:00"));
  const auto r = run_ris("sensor optical " + (d.path() / "s.toml").string() + " --sensor " +
                         (d.path() / "o.toml").string() + " --table " + table() + " -q -o " +
                         (d.path() / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const RasterF64 img = read_raster_f64(d.path() / "out" / "radiance.tif");
  EXPECT_EQ(img.cols, 80);
  EXPECT_EQ(img.rows, 60);
  EXPECT_EQ(img.bands, 4);
  EXPECT_DOUBLE_EQ(img.georef.geotransform[0], 690000.0);
  EXPECT_DOUBLE_EQ(img.georef.geotransform[3], 5330300.0);
  EXPECT_DOUBLE_EQ(img.georef.geotransform[1], 5.0);
  EXPECT_TRUE(std::filesystem::exists(d.path() / "out" / "preview.png"));
  const auto md = nlohmann::json::parse(read_file(d.path() / "out" / "metadata.json"));
  EXPECT_EQ(md["bands"].size(), 4u);
  EXPECT_GT(md["shadowed_cells"].get<int>(), 0);  // the pyramid in the evening sun
}

TEST(SensorCli, SameBytesForOneAndTwoThreads) {
  TempDir d;
  write_file(d.path() / "s.toml", kScene);
  write_file(d.path() / "o.toml", sensor_text("optical", "[\"red\", \"nir\"]", "08:00:00"));
  const std::string base = "sensor optical " + (d.path() / "s.toml").string() + " --sensor " +
                           (d.path() / "o.toml").string() + " --table " + table() + " -q -o ";
  ASSERT_EQ(run_ris(base + (d.path() / "a").string() + " --threads 1").exit_code, 0);
  ASSERT_EQ(run_ris(base + (d.path() / "b").string() + " --threads 2").exit_code, 0);
  EXPECT_EQ(read_file(d.path() / "a" / "radiance.tif"), read_file(d.path() / "b" / "radiance.tif"));
}

TEST(SensorCli, ThermalWritesBrightnessTemperature) {
  TempDir d;
  write_file(d.path() / "s.toml", kScene);
  write_file(d.path() / "t.toml", sensor_text("thermal", "[\"lwir\"]", "12:00:00"));
  const auto r = run_ris("sensor thermal " + (d.path() / "s.toml").string() + " --sensor " +
                         (d.path() / "t.toml").string() + " --table " + table() + " -q -o " +
                         (d.path() / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const RasterF64 img = read_raster_f64(d.path() / "out" / "brightness_temperature.tif");
  for (double v : img.data) {
    EXPECT_GT(v,
              280.0);  // a summer noon: warmer than the 288 K daily mean, emissivity < 1 lowers it
    EXPECT_LT(v, 340.0);
  }
}

TEST(SensorCli, BadInputsNameTheKeyAndWriteNothing) {
  TempDir d;
  write_file(d.path() / "s.toml", kScene);
  auto run = [&](const std::string& kind, const std::string& sensor) {
    write_file(d.path() / "x.toml", sensor);
    return run_ris("sensor " + kind + " " + (d.path() / "s.toml").string() + " --sensor " +
                   (d.path() / "x.toml").string() + " --table " + table() + " -o " +
                   (d.path() / "out").string());
  };
  auto r = run("optical", sensor_text("optical", "[\"uv\"]", "10:00:00"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("bands"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("uv"), std::string::npos) << r.output;
  r = run("thermal", sensor_text("optical", "[\"red\"]", "10:00:00"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("kind"), std::string::npos) << r.output;
  write_file(d.path() / "bad.csv",
             "id,name,emissivity_lwir,emissivity_mwir,albedo,thermal_inertia,rho_blue,rho_green,"
             "rho_red,rho_nir\n"
             "21,grass,1.3,0.96,0.23,800,0.04,0.09,0.05,0.45\n");
  write_file(d.path() / "x.toml", sensor_text("thermal", "[\"lwir\"]", "10:00:00"));
  r = run_ris("sensor thermal " + (d.path() / "s.toml").string() + " --sensor " +
              (d.path() / "x.toml").string() + " --table " + (d.path() / "bad.csv").string() +
              " -o " + (d.path() / "out").string());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("emissivity_lwir (category 21)"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(d.path() / "out"));
}

TEST(SensorCli, NightWarnsAndRendersDark) {
  TempDir d;
  write_file(d.path() / "s.toml", kScene);
  write_file(d.path() / "o.toml",
             "kind = \"optical\"\ndate = \"2024-06-21\"\ntime = \"23:00:00\"\nbands = [\"red\"]\n");
  const auto r = run_ris("sensor optical " + (d.path() / "s.toml").string() + " --sensor " +
                         (d.path() / "o.toml").string() + " --table " + table() + " -o " +
                         (d.path() / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("below the horizon"), std::string::npos) << r.output;
  const RasterF64 img = read_raster_f64(d.path() / "out" / "radiance.tif");
  for (double v : img.data) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace ris
