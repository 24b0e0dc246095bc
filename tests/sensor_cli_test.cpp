// End-to-end runs of `ris sensor optical|thermal` (docs/sensors.md).
#include <gdal.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
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
namespace fs = std::filesystem;

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

const char* kCamera = R"(
[camera]
position = [690200, 5330000]   # the scene's south edge, below the pyramid
altitude = "300 m"
heading = "0 deg"
depression = "60 deg"
fov = "30 deg"
columns = 64
rows = 48
mtf_at_nyquist = 0.3
[detector]
electrons_per_radiance = 150
read_noise = 15
full_well = 30000
bits = 12
)";

// A frame camera: its picture, range and footprint layers, digital numbers
// (UInt16), GCPs in the scene's CRS that lie on the scene, and the
// metadata's camera block.
TEST(SensorCli, FrameCameraWritesItsPictureWithGcps) {
  TempDir d;
  write_file(d.path() / "s.toml", kScene);
  write_file(d.path() / "o.toml",
             sensor_text("optical", "[\"blue\", \"green\", \"red\"]", "10:30:00") + kCamera);
  const auto r = run_ris("sensor optical " + (d.path() / "s.toml").string() + " --sensor " +
                         (d.path() / "o.toml").string() + " --table " + table() + " -q -o " +
                         (d.path() / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path out = d.path() / "out";
  for (const char* f : {"camera_radiance.tif", "camera_range_m.tif", "camera_footprint_area_m2.tif",
                        "camera_digital_number.tif", "camera_preview.png", "radiance.tif"}) {
    EXPECT_TRUE(fs::exists(out / f)) << f;
  }
  const RasterF64 img = read_raster_f64(out / "camera_radiance.tif");
  EXPECT_EQ(img.cols, 64);
  EXPECT_EQ(img.rows, 48);
  EXPECT_EQ(img.bands, 3);
  const RasterF64 range = read_raster_f64(out / "camera_range_m.tif");
  // The lowest rows look at the ground near the south edge, 300 m below.
  const double bottom = range.data[47 * 64 + 32];
  EXPECT_GT(bottom, 300.0);
  EXPECT_LT(bottom, 300.0 / std::sin(45.0 * 3.14159265358979 / 180.0));
  GDALAllRegister();
  GDALDatasetH ds = GDALOpen((out / "camera_digital_number.tif").c_str(), GA_ReadOnly);
  ASSERT_NE(ds, nullptr);
  EXPECT_EQ(GDALGetRasterDataType(GDALGetRasterBand(ds, 1)), GDT_UInt16);
  const int n = GDALGetGCPCount(ds);
  EXPECT_GT(n, 3);
  const GDAL_GCP* g = GDALGetGCPs(ds);
  for (int i = 0; i < n; ++i) {
    EXPECT_GE(g[i].dfGCPX, 690000.0);
    EXPECT_LE(g[i].dfGCPX, 690400.0);
    EXPECT_GE(g[i].dfGCPY, 5330000.0);
    EXPECT_LE(g[i].dfGCPY, 5330300.0);
  }
  EXPECT_NE(std::string(GDALGetGCPProjection(ds)).find("32632"), std::string::npos);
  GDALClose(ds);
  const auto md = nlohmann::json::parse(read_file(out / "metadata.json"));
  EXPECT_EQ(md["camera"]["columns"].get<int>(), 64);
  EXPECT_TRUE(md["camera"]["digital_numbers"].get<bool>());
}

// Without --table the table is the one named after the scene's library: the
// standard scene's crops (ku-geometric-eo.csv), which the generic table
// lacks.
TEST(SensorCli, DefaultTableFollowsTheScenesLibrary) {
  TempDir d;
  write_file(d.path() / "o.toml",
             sensor_text("optical", "[\"red\"]", "10:00:00") + "latitude = 39\nlongitude = -95\n");
  const auto r = run_ris("sensor optical " + std::string(test::data_dir()) +
                         "/scenes/ku-geometric.toml --sensor " + (d.path() / "o.toml").string() +
                         " -q -o " + (d.path() / "out").string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto md = nlohmann::json::parse(read_file(d.path() / "out" / "metadata.json"));
  EXPECT_NE(md["surface_table"].get<std::string>().find("ku-geometric-eo.csv"), std::string::npos);
}

// The bench's camera line runs and prints its figure (no speed is asserted:
// speed goals live in the bench's printout, docs/sensors.md).
TEST(SensorCli, BenchPrintsTheCameraRayRate) {
  const auto r = run_ris("bench --camera --repeats 1");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("camera_rays_per_s="), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("terrain BVH"), std::string::npos) << r.output;
}

TEST(SensorCli, BadCamerasNameTheKeyAndWriteNothing) {
  TempDir d;
  write_file(d.path() / "s.toml", kScene);
  auto run = [&](const std::string& kind, const std::string& sensor) {
    write_file(d.path() / "x.toml", sensor);
    return run_ris("sensor " + kind + " " + (d.path() / "s.toml").string() + " --sensor " +
                   (d.path() / "x.toml").string() + " --table " + table() + " -o " +
                   (d.path() / "out").string());
  };
  const std::string optical = sensor_text("optical", "[\"red\"]", "10:00:00");
  auto r = run("optical", optical +
                              "[camera]\nposition = [0, 0]\naltitude = 100\n"
                              "columns = 16384\nrows = 16384\nsamples = 8\n");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("camera.samples"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("fewer pixels or samples"), std::string::npos) << r.output;
  r = run("optical", optical +
                         "[camera]\nposition = [0, 0]\naltitude = 100\n"
                         "depression = \"-10 deg\"\n");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("camera.depression"), std::string::npos) << r.output;
  r = run("optical", optical +
                         "[camera]\nposition = [0, 0]\naltitude = 100\n"
                         "mtf_at_nyquist = 0\n");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("camera.mtf_at_nyquist"), std::string::npos) << r.output;
  r = run("thermal", sensor_text("thermal", "[\"lwir\"]", "10:00:00") +
                         "[camera]\nposition = [0, 0]\naltitude = 100\n[detector]\n"
                         "electrons_per_radiance = 1\nfull_well = 10\n");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("NETD"), std::string::npos) << r.output;
  r = run("optical", optical + "[detector]\nelectrons_per_radiance = 1\nfull_well = 10\n");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("[camera]"), std::string::npos) << r.output;
  r = run("optical", optical + "[camera]\nposition = [690250, 5330200]\naltitude = 10\n");
  EXPECT_NE(r.exit_code, 0);  // the pyramid's top (its centre: x, y are its corner) is 57 m
  EXPECT_NE(r.output.find("camera.altitude"), std::string::npos) << r.output;
  r = run("optical", optical +
                         "[camera]\nposition = [690200, 5330150]\naltitude = 500\n"
                         "depression = 0\n");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("sees none of the scene"), std::string::npos) << r.output;
  r = run("optical", sensor_text("optical", "[\"red\", \"red\"]", "10:00:00"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("twice"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(d.path() / "out"));
}

}  // namespace
}  // namespace ris
