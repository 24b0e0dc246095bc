// End-to-end: `ris simulate --acquisition` on the shipped NISAR product
// (winnipeg.h5 with its DEM): the products lie on the product's 250 x 250
// grid and metadata.json names the acquisition; bad combinations fail with
// the option named.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <nlohmann/json.hpp>

#include "acquisition_paths.h"
#include "ris/io/raster_io.h"
#include "test_util.h"

namespace ris {
namespace {

TEST(SimulateAcquisitionCli, WinnipegOnTheProductGrid) {
  test::TempDir tmp;
  const auto r = test::run_ris("simulate -a " + test::winnipeg_h5() + " --dem " +
                               test::test_dem("winnipeg_dem.tif") + " --out " +
                               (tmp / "w").string() + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("of the product's 250 x 250 grid"), std::string::npos) << r.output;
  for (const char* f : {"mean_power_slant.tif", "speckled_power_slant.tif", "mask_slant.tif",
                        "local_incidence.tif", "layover_shadow_mask.tif"}) {
    const RasterF64 img = read_raster_f64(tmp / "w" / f);
    EXPECT_EQ(img.rows, 250) << f;
    EXPECT_EQ(img.cols, 250) << f;
  }
  const RasterF64 power = read_raster_f64(tmp / "w" / "mean_power_slant.tif");
  std::size_t positive = 0;
  for (double p : power.data) positive += std::isfinite(p) && p > 0.0;
  EXPECT_EQ(positive, power.data.size());
  const auto md = nlohmann::json::parse(test::read_file(tmp / "w" / "metadata.json"));
  EXPECT_EQ(md["acquisition"]["path"], test::winnipeg_h5());
  EXPECT_EQ(md["acquisition"]["mission"], "UAVSAR");
  EXPECT_EQ(md["acquisition"]["grid"]["lines"], 250);
  EXPECT_EQ(md["acquisition"]["window"]["bins"], 250);
  EXPECT_EQ(md["earth_model"], "ellipsoid");
  EXPECT_TRUE(md["products"].contains("slant_range.png"));
}

TEST(SimulateAcquisitionCli, FlatEarthOnRequest) {
  test::TempDir tmp;
  const auto r = test::run_ris("simulate -a " + test::winnipeg_h5() + " --dem " +
                               test::test_dem("winnipeg_dem.tif") + " --earth flat --out " +
                               (tmp / "f").string() + " --quiet --products mean_power_slant");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto md = nlohmann::json::parse(test::read_file(tmp / "f" / "metadata.json"));
  EXPECT_EQ(md["earth_model"], "flat");
  EXPECT_FALSE(std::filesystem::exists(tmp / "f" / "slant_range.png"));
}

TEST(SimulateAcquisitionCli, BadCombinationsNameTheOption) {
  test::TempDir tmp;
  const auto no_dem =
      test::run_ris("simulate -a " + test::winnipeg_h5() + " --out " + (tmp / "a").string());
  EXPECT_NE(no_dem.exit_code, 0);
  EXPECT_NE(no_dem.output.find("--dem"), std::string::npos) << no_dem.output;
  const auto scene_ellipsoid =
      test::run_ris("simulate --earth ellipsoid --out " + (tmp / "b").string());
  EXPECT_NE(scene_ellipsoid.exit_code, 0);
  EXPECT_NE(scene_ellipsoid.output.find("--acquisition"), std::string::npos)
      << scene_ellipsoid.output;
  const auto dem_alone = test::run_ris("simulate --dem " + test::test_dem("winnipeg_dem.tif") +
                                       " --out " + (tmp / "d").string());
  EXPECT_NE(dem_alone.exit_code, 0);
  EXPECT_NE(dem_alone.output.find("--acquisition"), std::string::npos) << dem_alone.output;
  EXPECT_FALSE(std::filesystem::exists(tmp / "d"));
  // Land cover needs a scene with a CRS (the standard scene has none).
  const auto no_crs = test::run_ris("simulate -a " + test::winnipeg_h5() + " --dem " +
                                    test::test_dem("winnipeg_dem.tif") + " --land-cover " +
                                    std::string(test::data_dir()) + "/scenes/ku-geometric.toml" +
                                    " --out " + (tmp / "e").string());
  EXPECT_NE(no_crs.exit_code, 0);
  EXPECT_NE(no_crs.output.find("ku-geometric.toml"), std::string::npos) << no_crs.output;
  EXPECT_NE(no_crs.output.find("no CRS"), std::string::npos) << no_crs.output;
  EXPECT_FALSE(std::filesystem::exists(tmp / "e"));
  EXPECT_FALSE(std::filesystem::exists(tmp / "a"));
  EXPECT_FALSE(std::filesystem::exists(tmp / "b"));
}

}  // namespace
}  // namespace ris
