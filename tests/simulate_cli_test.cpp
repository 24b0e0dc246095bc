// End-to-end: `ris simulate` on small hand-made inputs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"
#include "ris/scene/scene_io.h"
#include "test_inputs.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::run_ris;
using test::TempDir;
using test::write_file;

constexpr double kCell = 10.0;

// 60 rows x 200 columns of 10 m; the radar flies north 4 km west of it.
Scene small_scene() {
  Scene s = Scene::flat(60, 200, kCell, 0.0f, 1);
  // A box 120 m high, columns 80-99, rows 20-39, of category 2.
  for (int r = 20; r < 40; ++r) {
    for (int c = 80; c < 100; ++c) {
      s.elevation_m[s.index(r, c)] = 120.0f;
      s.category[s.index(r, c)] = 2;
    }
  }
  return s;
}

const std::string kRadar = test::kSmallSlarRadar;
const std::string kLibrary =
    test::constant_gamma_library({{1, "grass", -12.0, ""}, {2, "roof", -6.0, ""}});

const std::vector<std::string> kProducts = {
    "slant_range.png", "ground_range.png",   "mean_power_slant.tif",    "speckled_power_slant.tif",
    "mask_slant.tif",  "scene_mask.tif",     "local_incidence_deg.tif", "shadowmap.txt",
    "metadata.json",   "geocoded_power.tif", "geocoded_grey.tif"};

struct Inputs {
  TempDir dir;
  std::string scene, radar, library;
  explicit Inputs(const Scene& s, const std::string& radar_text = kRadar) {
    scene = (dir / "scene.tif").string();
    radar = (dir / "radar.toml").string();
    library = (dir / "library.toml").string();
    write_scene_geotiff(s, scene);
    write_file(radar, radar_text);
    write_file(library, kLibrary);
  }
  std::string args(const fs::path& out, const std::string& extra = "") const {
    return "simulate --scene " + scene + " --radar " + radar + " --backscatter " + library +
           " --out " + out.string() + " " + extra;
  }
};

// No staging folder (hidden entries) may be left beside the output.
void expect_no_staging_left(const fs::path& parent) {
  for (const auto& e : fs::directory_iterator(parent)) {
    EXPECT_NE(e.path().filename().string().front(), '.') << e.path();
  }
}

TEST(SimulateCli, WritesEveryProductWithConsistentShapes) {
  const Inputs in(small_scene());
  TempDir work;
  const fs::path out = work / "out";
  const auto r = run_ris(in.args(out, "--seed 3"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const std::string& p : kProducts) EXPECT_TRUE(fs::exists(out / p)) << p;
  expect_no_staging_left(work.path());
  EXPECT_NE(r.output.find(fs::absolute(out).string()), std::string::npos) << r.output;

  const nlohmann::json meta = nlohmann::json::parse(read_file(out / "metadata.json"));
  EXPECT_EQ(meta["software"]["version"], RIS_VERSION);
  EXPECT_EQ(meta["inputs"]["seed"], 3);
  EXPECT_EQ(meta["inputs"]["radar"]["polarisation"], "HH");
  const int bins = meta["derived"]["radar"]["range_bins"];
  const int lines = meta["derived"]["image"]["lines"];
  EXPECT_EQ(lines, 60);
  EXPECT_EQ(bins, 100);  // (c 10 us / 2) / (c 0.1 us / 2)

  // Shadow map: one row per line, one character per bin, the seed's alphabet,
  // and the box's shadow ('0') on the lines that cross it (scene rows 20-39
  // are lines 59-20 = 20..39 from the track start at the south edge).
  std::istringstream text(read_file(out / "shadowmap.txt"));
  std::vector<std::string> rows;
  for (std::string row; std::getline(text, row);) rows.push_back(row);
  ASSERT_EQ(static_cast<int>(rows.size()), lines);
  for (const std::string& row : rows) {
    ASSERT_EQ(static_cast<int>(row.size()), bins);
    EXPECT_EQ(row.find_first_not_of("0123456789#"), std::string::npos) << row;
  }
  EXPECT_NE(rows[30].find('0'), std::string::npos) << rows[30];
  EXPECT_EQ(rows[5].find('0'), std::string::npos) << rows[5];

  const RasterF64 mean = read_raster_f64(out / "mean_power_slant.tif");
  EXPECT_EQ(mean.cols, bins);
  EXPECT_EQ(mean.rows, lines);
  const RasterF64 mask = read_raster_f64(out / "scene_mask.tif");
  EXPECT_EQ(mask.cols, 200);
  EXPECT_EQ(mask.rows, 60);
  ASSERT_TRUE(mask.has_geotransform);
  EXPECT_DOUBLE_EQ(mask.georef.geotransform[1], kCell);
  const RasterF64 inc = read_raster_f64(out / "local_incidence_deg.tif");
  // A flat cell away from the box: local incidence = flat incidence.
  const double u = 4000.0 + 10.5 * kCell;
  EXPECT_NEAR(inc.data[static_cast<std::size_t>(5 * 200 + 10)],
              std::atan2(u, 3000.0) * 180.0 / 3.14159265358979, 1e-3);
}

TEST(SimulateCli, SameSeedGivesIdenticalBytesWithOneAndTwoThreads) {
  const Inputs in(small_scene());
  TempDir work;
  ASSERT_EQ(run_ris(in.args(work / "a", "--seed 11 --threads 1")).exit_code, 0);
  ASSERT_EQ(run_ris(in.args(work / "b", "--seed 11 --threads 2")).exit_code, 0);
  for (const char* p : {"slant_range.png", "ground_range.png", "mean_power_slant.tif",
                        "speckled_power_slant.tif", "mask_slant.tif", "shadowmap.txt"}) {
    EXPECT_EQ(read_file(work / "a" / p), read_file(work / "b" / p)) << p;
  }
  ASSERT_EQ(run_ris(in.args(work / "c", "--seed 12 --threads 2")).exit_code, 0);
  EXPECT_NE(read_file(work / "a" / "speckled_power_slant.tif"),
            read_file(work / "c" / "speckled_power_slant.tif"));
}

// A failing run exits non-zero, names the problem, and leaves the output
// folder as it was (here: an earlier file stays, nothing is added).
void expect_clean_failure(const Inputs& in, const std::string& expected_text) {
  TempDir work;
  const fs::path out = work / "out";
  fs::create_directories(out);
  write_file(out / "earlier.txt", "kept");
  const auto r = run_ris(in.args(out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find(expected_text), std::string::npos) << r.output;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
  EXPECT_EQ(names, std::vector<std::string>{"earlier.txt"});
  EXPECT_EQ(read_file(out / "earlier.txt"), "kept");
  expect_no_staging_left(work.path());
}

TEST(SimulateCli, TerrainAtOrAboveTheSensorFailsCleanly) {
  Scene s = small_scene();
  s.elevation_m[s.index(10, 10)] = 3000.0f;
  expect_clean_failure(Inputs(s), "altitude");
}

TEST(SimulateCli, SwathMissingTheSceneFailsCleanly) {
  std::string radar = kRadar;
  radar.replace(radar.find("33.4 us"), 7, "80 us");
  expect_clean_failure(Inputs(small_scene(), radar), "misses the scene");
}

TEST(SimulateCli, CategoryWithoutBackscatterFailsCleanly) {
  Scene s = small_scene();
  s.category[s.index(3, 3)] = 7;
  expect_clean_failure(Inputs(s), "category 7");
}

TEST(SimulateCli, NanElevationsAreCountedAsNoData) {
  Scene s = small_scene();
  int nans = 0;
  for (int r = 45; r < 50; ++r) {
    for (int c = 30; c < 36; ++c) {
      s.elevation_m[s.index(r, c)] = std::nanf("");
      s.valid[s.index(r, c)] = 0;
      ++nans;
    }
  }
  const Inputs in(s);
  TempDir work;
  const auto r = run_ris(in.args(work / "out"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json meta = nlohmann::json::parse(read_file(work / "out" / "metadata.json"));
  EXPECT_EQ(meta["inputs"]["scene"]["nodata_cells"], nans);
  EXPECT_EQ(meta["derived"]["geometry"]["nodata_samples"], nans);
  const RasterF64 mask = read_raster_f64(work / "out" / "scene_mask.tif");
  EXPECT_EQ(static_cast<int>(mask.data[static_cast<std::size_t>(47 * 200 + 33)]) & 4, 4);
  EXPECT_EQ(static_cast<int>(mask.data[static_cast<std::size_t>(47 * 200 + 40)]) & 4, 0);
}

}  // namespace
}  // namespace ris

namespace ris {
namespace {

// --products writes only the listed products (metadata.json always, listing
// them); --compress changes the files, not the pixels; bad values fail
// before anything is written, naming the option and the allowed values.
TEST(SimulateCli, ProductsAndCompressOptions) {
  const Inputs in(small_scene());
  TempDir work;
  const auto r =
      run_ris(in.args(work / "some", "--products slant_range,mask_slant --compress small"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(work / "some"))
    names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names,
            (std::vector<std::string>{"mask_slant.tif", "metadata.json", "slant_range.png"}));
  const nlohmann::json meta = nlohmann::json::parse(read_file(work / "some" / "metadata.json"));
  EXPECT_EQ(meta["products"].size(), 3u);

  ASSERT_EQ(run_ris(in.args(work / "all", "--compress none")).exit_code, 0);
  const RasterF64 small = read_raster_f64(work / "some" / "mask_slant.tif");
  const RasterF64 none = read_raster_f64(work / "all" / "mask_slant.tif");
  EXPECT_EQ(small.data, none.data);
  EXPECT_LT(fs::file_size(work / "some" / "mask_slant.tif"),
            fs::file_size(work / "all" / "mask_slant.tif"));

  for (const auto& [extra, text] :
       {std::pair<std::string, std::string>{"--products slant_range,bscope", "\"bscope\""},
        std::pair<std::string, std::string>{"--compress tiny", "\"fast\", \"small\" or \"none\""},
        std::pair<std::string, std::string>{"--stream --products slant_range,bscope",
                                            "\"bscope\""}}) {
    const auto bad = run_ris(in.args(work / "bad", extra));
    EXPECT_EQ(bad.exit_code, 1) << extra << bad.output;
    EXPECT_NE(bad.output.find(text), std::string::npos) << extra << bad.output;
    EXPECT_FALSE(fs::exists(work / "bad")) << extra;
  }
}

}  // namespace
}  // namespace ris
