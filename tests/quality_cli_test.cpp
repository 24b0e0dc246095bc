// `ris quality` end to end: a simulated product with its mask and the scene's
// categories, the real NISAR product's SLC layer, and bad input.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "build_paths.h"
#include "test_util.h"

namespace ris {
namespace {

TEST(QualityCli, SimulatedGeocodedProductWithCategoriesAndMask) {
  test::TempDir dir;
  const std::string out = (dir / "sim").string();
  ASSERT_EQ(test::run_ris("simulate --quiet --out " + out).exit_code, 0);
  ASSERT_EQ(test::run_ris("scene build -o " + (dir / "scene.tif").string()).exit_code, 0);
  // The geocoded power is on the scene grid: the scene's band 2 are its categories.
  const auto r = test::run_ris("quality --json " + out + "/geocoded_power.tif --categories " +
                               (dir / "scene.tif").string() + " --categories-band 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["categories"].size(), 10u);
  EXPECT_EQ(j["pairs"].size(), 45u);
  // The figure-4-5 radar's fading: N = 1 to 1.1 independent samples.
  EXPECT_GT(j["speckle"]["enl"].get<double>(), 0.9);
  EXPECT_LT(j["speckle"]["enl"].get<double>(), 1.25);
  for (const auto& p : j["pairs"]) {
    EXPECT_GE(p["jeffries_matusita"].get<double>(), 0.0);
    EXPECT_LE(p["jeffries_matusita"].get<double>(), 2.0);
  }
  // The slant-range image with its mask: shadow edges measured.
  const auto m = test::run_ris("quality --json " + out + "/speckled_power_slant.tif --mask " + out +
                               "/mask_slant.tif");
  ASSERT_EQ(m.exit_code, 0) << m.output;
  EXPECT_GT(nlohmann::json::parse(m.output)["edges"]["edges"].get<int>(), 100);
  // A mask of another size is refused, naming the option.
  const auto bad = test::run_ris("quality " + out + "/speckled_power_slant.tif --mask " + out +
                                 "/scene_mask.tif");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--mask"), std::string::npos) << bad.output;
}

TEST(QualityCli, RealNisarProductsSlcLayer) {
  const std::string h5 = std::string(ris::test::test_data_dir()) + "/real/winnipeg.h5";
  const auto r = test::run_ris("quality --json " + h5);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["image"]["cols"].get<int>(), 250);
  EXPECT_EQ(j["image"]["read_as"].get<std::string>(), "complex |z|^2");
  EXPECT_NE(j["image"]["source"].get<std::string>().find("frequencyA/HH"), std::string::npos);
  const auto none = test::run_ris("quality " + h5 + " --band 5");
  EXPECT_NE(none.exit_code, 0);
  EXPECT_NE(none.output.find("the product has 1 (HH)"), std::string::npos) << none.output;
}

TEST(QualityCli, BadInputGivesAClearError) {
  test::TempDir dir;
  EXPECT_NE(test::run_ris("quality " + (dir / "missing.tif").string()).exit_code, 0);
  const auto r = test::run_ris("quality x.tif --scale linear");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--scale"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace ris
