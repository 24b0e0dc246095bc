#include "ris/sensors_eo/surface_table.h"

#include <gtest/gtest.h>

#include <string>

#include "build_paths.h"
#include "ris/util/error.h"

namespace ris {
namespace {

const std::string kHeader =
    "id,name,emissivity_lwir,emissivity_mwir,albedo,thermal_inertia,rho_blue,rho_green,rho_red,rho_"
    "nir\n";

std::string error_of(const std::string& text) {
  try {
    parse_eo_surface_table(text, "t.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(EoSurfaceTable, ParsesRowsAndBandProperties) {
  const EoSurfaceTable t = parse_eo_surface_table(
      "# comment\n" + kHeader + "21,grass,0.98,0.96,0.23,800,0.04,0.09,0.05,0.45\n", "t.csv");
  const EoSurface& g = t.at(21);
  EXPECT_EQ(g.name, "grass");
  EXPECT_DOUBLE_EQ(band_property(g, EoBand::lwir), 0.98);
  EXPECT_DOUBLE_EQ(band_property(g, EoBand::mwir), 0.96);
  EXPECT_DOUBLE_EQ(band_property(g, EoBand::nir), 0.45);
  EXPECT_DOUBLE_EQ(band_property(g, EoBand::blue), 0.04);
  EXPECT_DOUBLE_EQ(g.thermal_inertia, 800);
  EXPECT_THROW(t.at(22), InputError);
}

TEST(EoSurfaceTable, RefusesEmissivityOutsideZeroOneNamingTheKey) {
  const std::string msg = error_of(kHeader + "21,grass,1.2,0.96,0.23,800,0.04,0.09,0.05,0.45\n");
  EXPECT_NE(msg.find("t.csv"), std::string::npos) << msg;
  EXPECT_NE(msg.find("emissivity_lwir (category 21)"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[0, 1]"), std::string::npos) << msg;
  EXPECT_NE(
      error_of(kHeader + "21,grass,0.9,0.96,0.23,-5,0.04,0.09,0.05,0.45\n").find("thermal_inertia"),
      std::string::npos);
  EXPECT_NE(error_of(kHeader + "21,grass,0.9,0.96,0.23,800,0.04,x,0.05,0.45\n").find("rho_green"),
            std::string::npos);
  EXPECT_NE(error_of("id,name\n").find("header"), std::string::npos);
}

TEST(EoSurfaceTable, UnknownBandNamesTheKeyAndTheChoices) {
  try {
    parse_eo_band("swir", "s.toml", "bands");
    FAIL();
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("bands"), std::string::npos) << msg;
    EXPECT_NE(msg.find("swir"), std::string::npos) << msg;
    EXPECT_NE(msg.find("lwir"), std::string::npos) << msg;
  }
  EXPECT_EQ(parse_eo_band("nir", "s.toml", "bands"), EoBand::nir);
}

TEST(EoSurfaceTable, ShippedTableCoversTheGenericCategories) {
  const EoSurfaceTable t =
      load_eo_surface_table(std::string(test::data_dir()) + "/sensors_eo/generic-terrain-eo.csv");
  for (int id = 20; id <= 27; ++id) EXPECT_NO_THROW(t.at(id)) << id;
  EXPECT_EQ(t.by_category.size(), 8u);
}

}  // namespace
}  // namespace ris
