// End-to-end: `ris simulate` dispatching on the radar's mode (SAR with point
// targets and their impulse-response measurements; PPI products), and bad
// input leaving nothing behind.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>
#include <vector>

#include "build_paths.h"
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

const std::string kLibrary = test::constant_gamma_library({{1, "grass", -15.0, ""}});

const char* kSar = R"(
mode = "sar"
frequency = "9.6 GHz"
polarisation = "VV"
near_range = "1420 m"
far_range = "1550 m"
range_bin = "1 m"
[sar]
range_resolution = "3 m"
azimuth_resolution = "3 m"
nesz_db = -30
coherent = true
[track]
altitude = "1000 m"
near_edge_distance = "1000 m"
)";

const char* kPpi = R"(
mode = "ppi"
frequency = "9.41 GHz"
polarisation = "HH"
pulse_width = "50 ns"
near_range = 0
far_range = "120 m"
azimuth_beamwidth = "2 deg"
[site]
position = [100.0, 130.0]
height = "30 m"
[scan]
range_rings = "50 m"
)";

struct Inputs {
  TempDir dir;
  std::string scene, library;
  Inputs() {
    scene = (dir / "scene.tif").string();
    library = (dir / "library.toml").string();
    write_scene_geotiff(Scene::flat(260, 200, 1.0, 0.0f, 1), scene);
    write_file(library, kLibrary);
  }
  std::string args(const std::string& radar_text, const fs::path& out,
                   const std::string& extra = "") const {
    const std::string radar = (dir / "radar.toml").string();
    write_file(radar, radar_text);
    return "simulate --scene " + scene + " --radar " + radar + " --backscatter " + library +
           " --out " + out.string() + " " + extra;
  }
};

TEST(ModesCli, CoherentSarMeasuresTheTargetsImpulseResponse) {
  Inputs in;
  const std::string targets = (in.dir / "targets.toml").string();
  write_file(targets, "[[target]]\nname = \"cr\"\nposition = [100.5, 130.5]\nrcs_db = 50\n");
  const fs::path out = in.dir / "out";
  const auto r = run_ris(in.args(kSar, out, "--targets " + targets));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("PSLR"), std::string::npos) << r.output;
  const auto meta = nlohmann::json::parse(read_file(out / "metadata.json"));
  EXPECT_EQ(meta["mode"], "sar");
  ASSERT_EQ(meta["point_targets"]["seen"].size(), 1u);
  const auto& irf = meta["point_targets"]["seen"][0];
  EXPECT_NEAR(irf["range_resolution_3db_m"].get<double>(), 3.0, 0.3);
  EXPECT_NEAR(irf["azimuth_resolution_3db_m"].get<double>(), 3.0, 0.3);
  EXPECT_TRUE(fs::exists(out / "slant_range.png"));

  // `ris irf` on the saved image re-measures the same numbers.
  const fs::path json = in.dir / "irf.json";
  const std::string image = (out / "speckled_power_slant.tif").string();
  const auto m =
      run_ris("irf " + image + " --line " + std::to_string(irf["peak_line"].get<int>()) +
              " --bin " + std::to_string(irf["peak_bin"].get<int>()) + " --json " + json.string());
  ASSERT_EQ(m.exit_code, 0) << m.output;
  const auto again = nlohmann::json::parse(read_file(json));
  EXPECT_NEAR(again["range_resolution_3db_m"].get<double>(),
              irf["range_resolution_3db_m"].get<double>(), 1e-9);
  EXPECT_NEAR(again["azimuth_pslr_db"].get<double>(), irf["azimuth_pslr_db"].get<double>(), 1e-9);
  // Bad input: a pixel off the image; a raster without pixel sizes.
  auto bad = run_ris("irf " + image + " --line 100000 --bin 3");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("outside"), std::string::npos) << bad.output;
  bad = run_ris("irf " + in.scene + " --line 3 --bin 3");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("expected one band"), std::string::npos) << bad.output;
  const std::string plain = (in.dir / "plain.tif").string();
  const std::vector<float> ones(64, 1.0f);
  write_geotiff<float>(plain, ones.data(), 8, 8, nullptr, std::nullopt, {}, "power");
  bad = run_ris("irf " + plain + " --line 3 --bin 3");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--range-pixel"), std::string::npos) << bad.output;
  EXPECT_EQ(
      run_ris("irf " + plain + " --line 3 --bin 3 --range-pixel 1 --azimuth-pixel 1").exit_code, 0);
}

TEST(ModesCli, PpiWritesScopeAndBScope) {
  Inputs in;
  const fs::path out = in.dir / "out";
  const auto r = run_ris(in.args(kPpi, out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const char* f :
       {"ppi_scope.png", "ppi_scope_power.tif", "ppi_scope_mask.tif", "bscope.png",
        "mean_power_bscope.tif", "speckled_power_bscope.tif", "mask_bscope.tif", "metadata.json"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  const auto meta = nlohmann::json::parse(read_file(out / "metadata.json"));
  EXPECT_EQ(meta["mode"], "ppi");
  EXPECT_EQ(meta["derived"]["rays"]["in_sector"], 360);
}

TEST(ModesCli, BadPpiSiteAndOffSceneTargetLeaveNothingBehind) {
  Inputs in;
  const fs::path out = in.dir / "out";
  std::string bad = kPpi;
  bad.replace(bad.find("[100.0, 130.0]"), 14, "[900.0, 130.0]");
  auto r = run_ris(in.args(bad, out));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("site.position"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
  const std::string targets = (in.dir / "targets.toml").string();
  write_file(targets, "[[target]]\nposition = [5000.0, 130.0]\nrcs = 10\n");
  r = run_ris(in.args(kSar, out, "--targets " + targets));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("target[0].position"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("off the scene"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(ModesCli, ShippedSarAndPpiRadarsRunOnTheStandardScene) {
  TempDir dir;
  const std::string data = ris::test::data_dir();
  // The example SAR with the example corner reflectors: every reflector seen
  // and measured at the design resolution, 2 looks x 7.5 m = 15 m, within 10%.
  const fs::path sar_out = dir / "sar";
  auto r =
      run_ris("simulate --quiet --radar " + data + "/radars/sar-x-band-stripmap.toml" +
              " --targets " + data + "/targets/corner-reflectors.toml --out " + sar_out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto meta = nlohmann::json::parse(read_file(sar_out / "metadata.json"));
  ASSERT_EQ(meta["point_targets"]["seen"].size(), 3u) << meta["point_targets"].dump(2);
  for (const auto& irf : meta["point_targets"]["seen"]) {
    EXPECT_NEAR(irf["range_resolution_3db_m"].get<double>(), 15.0, 1.5) << irf.dump();
    EXPECT_NEAR(irf["azimuth_resolution_3db_m"].get<double>(), 15.0, 1.5) << irf.dump();
  }
  for (const char* radar : {"ppi-ground-mast-30m.toml", "ppi-airborne-nav-10000ft.toml"}) {
    const fs::path out = dir / radar;
    r = run_ris("simulate --quiet --radar " + data + "/radars/" + radar + " --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << radar << "\n" << r.output;
    EXPECT_TRUE(fs::exists(out / "ppi_scope.png")) << radar;
  }
}

}  // namespace
}  // namespace ris
