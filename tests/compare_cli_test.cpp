// `ris compare` end to end: a simulation against another fading seed of
// itself on the scene grid with the geometry-only baselines, the output
// folder, and bad input (sizes without geocoding, noise).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

TEST(CompareCli, SimulationAgainstAnotherSeedWithBaselinesAndPictures) {
  test::TempDir dir;
  const std::string a = (dir / "a").string(), b = (dir / "b").string();
  ASSERT_EQ(test::run_ris("simulate --quiet --out " + a).exit_code, 0);
  ASSERT_EQ(test::run_ris("simulate --quiet --seed 5 --out " + b).exit_code, 0);
  const std::string out = (dir / "cmp").string();
  const auto r = test::run_ris("compare --json " + a + "/geocoded_power.tif " + b +
                               "/geocoded_power.tif --local-incidence " + a +
                               "/local_incidence_deg.tif --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  // The same scene and geometry: registered in place within the scatter two
  // independent speckle patterns leave in the correlation peak (measured
  // 0.08 pixels; a shifted copy of one image registers within 0.01,
  // src/image/quality/image_comparison_test.cpp), and the correlation grows
  // as the windows average the speckle away.
  EXPECT_NEAR(j["registration"]["shift_x_px"].get<double>(), 0.0, 0.2);
  EXPECT_NEAR(j["registration"]["shift_y_px"].get<double>(), 0.0, 0.2);
  const auto& g = j["agreement"];
  ASSERT_EQ(g.size(), 4u);
  EXPECT_LT(g[0]["pearson"].get<double>(), g[3]["pearson"].get<double>());
  EXPECT_GT(g[3]["pearson"].get<double>(), 0.8);
  // The same radar: no bias beyond speckle's (9 x 9 averages: ~0.1 dB).
  EXPECT_NEAR(g[3]["bias_db"].get<double>(), 0.0, 0.1);
  ASSERT_TRUE(j.contains("baselines"));
  EXPECT_EQ(j["baselines"]["muhleman"].size(), 4u);
  for (const char* f : {"sheet.png", "histograms.png", "compare.json"}) {
    EXPECT_TRUE(fs::exists(fs::path(out) / f)) << f;
  }
}

TEST(CompareCli, ImagesOfDifferentSizesWithoutGeocodingAreRefused) {
  test::TempDir dir;
  const std::string a = (dir / "a").string();
  ASSERT_EQ(test::run_ris("simulate --quiet --out " + a).exit_code, 0);
  const std::string out = (dir / "cmp").string();
  // Slant range (241 x 700, no CRS) against the scene grid (1000 x 700).
  const auto r = test::run_ris("compare " + a + "/mean_power_slant.tif " + a +
                               "/geocoded_power.tif --out " + out);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("not both georeferenced"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace ris
