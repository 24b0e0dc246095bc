// The fault plan (ris/sim/fault_plan.h): read from the environment only by
// fault_plan_from_environment, strictly; a plan in a streamed run's options
// fails that run's block and leaves no output; the library never reads the
// environment itself.
#include "ris/sim/fault_plan.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "build_paths.h"
#include "ris/scene/scene_io.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/ppi_stream.h"
#include "ris/sim/slar_stream.h"
#include "ris/util/error.h"
#include "slar_fixtures.h"
#include "stream_fixtures.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

constexpr const char* kVariables[] = {"RIS_FAIL_BLOCK", "RIS_FAIL_GEO_BLOCK", "RIS_FAIL_MAPS_BLOCK",
                                      "RIS_KILL_BLOCK"};

// Sets the fault variables for one test and restores them (unset) after.
struct FaultEnvironment {
  FaultEnvironment() {
    for (const char* v : kVariables) ::unsetenv(v);
  }
  ~FaultEnvironment() {
    for (const char* v : kVariables) ::unsetenv(v);
  }
  void set(const char* name, const char* value) { ::setenv(name, value, 1); }
};

TEST(FaultPlan, NoneWhenTheVariablesAreUnsetOrEmpty) {
  FaultEnvironment env;
  EXPECT_FALSE(fault_plan_from_environment().any());
  env.set("RIS_FAIL_BLOCK", "");
  EXPECT_FALSE(fault_plan_from_environment().any());
}

TEST(FaultPlan, EachVariableSetsItsOwnBlock) {
  FaultEnvironment env;
  env.set("RIS_FAIL_BLOCK", "3");
  env.set("RIS_FAIL_GEO_BLOCK", "0");
  env.set("RIS_FAIL_MAPS_BLOCK", "12");
  env.set("RIS_KILL_BLOCK", "7");
  const FaultPlan p = fault_plan_from_environment();
  EXPECT_EQ(p.line_block, 3);
  EXPECT_EQ(p.geocoding_block, 0);
  EXPECT_EQ(p.maps_block, 12);
  EXPECT_EQ(p.kill_block, 7);
  EXPECT_TRUE(p.any());
}

TEST(FaultPlan, AValueThatIsNotABlockIndexIsRefusedNamingTheVariable) {
  // atoi took each of these as a block (most as block 0, so a typo failed
  // the first block of a real run).
  for (const char* bad : {"x", "3x", "-1", " 3", "1e2", "99999999999"}) {
    FaultEnvironment env;
    env.set("RIS_FAIL_GEO_BLOCK", bad);
    try {
      (void)fault_plan_from_environment();
      ADD_FAILURE() << "'" << bad << "' was accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.key(), "RIS_FAIL_GEO_BLOCK") << bad;
      EXPECT_NE(std::string(e.what()).find("non-negative integer"), std::string::npos) << e.what();
    }
  }
}

// A streamed SLAR run of a small scene file (tests/slar_fixtures.h).
struct StreamCase {
  test::TempDir dir;
  Scene scene = test::rugged_test_scene();
  fs::path scene_path = dir / "scene.tif";
  RadarParams radar;
  test::CosineSigma0Source sigma0{{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10}};
  SlarRunInfo info;
  StreamCase() {
    write_scene_geotiff(scene, scene_path);
    radar = test::stream_test_radar(scene, 0.0);
    info = SlarRunInfo{scene_path.string(), "r.toml", "test", 7, 1};
  }
  SlarStreamSummary run(const fs::path& out, const FaultPlan& faults) const {
    SlarStreamOptions o;
    o.block_lines = 7;
    o.quiet = true;
    o.faults = faults;
    return simulate_slar_streamed(scene_path, radar, sigma0, info, out, o);
  }
};

TEST(FaultPlan, APlanInTheOptionsFailsThatBlockAndLeavesNoOutput) {
  const StreamCase c;
  FaultPlan lines;
  lines.line_block = 2;
  FaultPlan geocoding;
  geocoding.geocoding_block = 0;  // a small scene: one geocoding block
  for (const auto& [plan, words] : {std::pair{lines, "block 2: a failure injected"},
                                    std::pair{geocoding, "geocoding block 0: a failure"}}) {
    const fs::path out = c.dir / "out";
    try {
      (void)c.run(out, plan);
      ADD_FAILURE() << "the run did not fail (" << words << ")";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(out)) << words;
    for (const auto& e : fs::directory_iterator(c.dir.path())) {
      EXPECT_EQ(e.path().filename().string().find(".partial"), std::string::npos) << e.path();
    }
  }
}

TEST(FaultPlan, TheLibraryDoesNotReadTheEnvironment) {
  // Only `ris simulate` (fault_plan_from_environment) reads the variables:
  // a run through the library with the default plan ignores them.
  FaultEnvironment env;
  env.set("RIS_FAIL_BLOCK", "0");
  env.set("RIS_FAIL_GEO_BLOCK", "0");
  const StreamCase c;
  const fs::path out = c.dir / "out";
  EXPECT_NO_THROW((void)c.run(out, FaultPlan{}));
  EXPECT_TRUE(fs::exists(out / "metadata.json"));
}

TEST(FaultPlan, AStreamedPpiFailsThePlannedBlock) {
  const StreamCase c;
  // The shipped mast radar with its site moved onto the test scene.
  RadarParams ppi = load_radar(std::string(test::data_dir()) + "/radars/ppi-ground-mast-30m.toml");
  const auto [x, y] = c.scene.world_from_grid(0.47 * c.scene.cols, 0.53 * c.scene.rows);
  ppi.ppi.site_x_m = x;
  ppi.ppi.site_y_m = y;
  PpiStreamOptions o;
  o.block_rays = 64;
  o.quiet = true;
  o.faults.line_block = 1;
  const fs::path out = c.dir / "ppi";
  EXPECT_THROW((void)simulate_ppi_streamed(c.scene_path, ppi, c.sigma0, c.info, out, o),
               std::runtime_error);
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace ris
