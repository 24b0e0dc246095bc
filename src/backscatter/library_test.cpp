#include "ris/backscatter/library.h"
#include "build_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

using test::TempDir;
using test::write_file;

double db(double x) {
  return 10.0 * std::log10(x);
}

// The InputError message of loading `text` as a library, or "" if it loads.
std::string load_error(const std::string& text, const std::string& name = "lib.toml") {
  TempDir dir;
  write_file(dir / name, text);
  try {
    auto src = load_sigma0_source((dir / name).string());
    for (std::uint16_t id : src->category_ids()) {
      src->sigma0(id, deg_to_rad(30.0), RadarBand{8.6e9, Polarisation::HH});
    }
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Library, LoadsCategoriesWithNamesColoursAndModels) {
  TempDir dir;
  write_file(dir / "t.csv",
             "category,frequency_ghz,polarisation,angle_deg,sigma0_db\n"
             "2,8.6,HH,0,-4\n2,8.6,HH,90,-22\n");
  write_file(dir / "lib.toml", R"(
[library]
name = "test"
[[category]]
id = 1
name = "grass"
colour = "#10ff20"
[category.model]
name = "muhleman"
[[category]]
id = 2
name = "corn"
colour = "#000000"
[category.model]
name = "constant_gamma"
gamma_db = -10.0
[[category.band]]
frequency = ["8 GHz", "9 GHz"]
polarisation = ["HH"]
[category.band.model]
name = "table"
file = "t.csv"
)");
  auto src = load_sigma0_source((dir / "lib.toml").string());
  EXPECT_EQ(src->category_ids(), (std::vector<std::uint16_t>{1, 2}));
  EXPECT_EQ(src->category_name(1), "grass");
  EXPECT_EQ(*src->category_colour(1), (std::array<std::uint8_t, 3>{0x10, 0xff, 0x20}));
  EXPECT_FALSE(src->has_category(3));
  // Muhleman at 30 deg: 0.0118 cos30 / (sin30 + 0.111 cos30)^3 = 0.048246 (-13.166 dB),
  // MODEL.md section 4.
  EXPECT_NEAR(db(src->sigma0(1, deg_to_rad(30.0), {8.6e9, Polarisation::VV})), -13.166, 0.001);
  // Category 2 at 8.6 GHz HH: the table, -4 dB at 0 and -22 dB at 90 -> -10 dB at 30 deg.
  EXPECT_NEAR(db(src->sigma0(2, deg_to_rad(30.0), {8.6e9, Polarisation::HH})), -10.0, 1e-9);
  // Other bands: constant gamma, -10 dB + 10 log10(cos 60 deg) = -13.010 dB.
  EXPECT_NEAR(db(src->sigma0(2, deg_to_rad(60.0), {8.6e9, Polarisation::VV})), -13.0103, 1e-4);
  EXPECT_NEAR(db(src->sigma0(2, deg_to_rad(60.0), {13e9, Polarisation::HH})), -13.0103, 1e-4);
}

TEST(Library, CsvTableIsASourceToo) {
  TempDir dir;
  write_file(dir / "t.csv",
             "# category 7: milo\ncategory,frequency_ghz,polarisation,angle_deg,sigma0_db\n"
             "7,8.6,VV,0,-4\n7,8.6,VV,90,-22\n");
  auto src = load_sigma0_source((dir / "t.csv").string());
  EXPECT_TRUE(src->has_category(7));
  EXPECT_EQ(src->category_name(7), "milo");
  EXPECT_NEAR(db(src->sigma0(7, deg_to_rad(45.0), {8.6e9, Polarisation::VV})), -13.0, 1e-9);
  EXPECT_THROW(src->sigma0(7, 0.5, {8.6e9, Polarisation::HH}), InputError);
}

TEST(Library, BadLibrariesNameFileAndKey) {
  const std::string head = "[[category]]\nid = 1\nname = \"a\"\ncolour = \"#102030\"\n";
  std::string e = load_error(head + "[category.model]\nname = \"nosuch\"\n");
  EXPECT_NE(e.find("lib.toml"), std::string::npos) << e;
  EXPECT_NE(e.find("category[0].model.name"), std::string::npos) << e;
  EXPECT_NE(e.find("unknown backscatter model \"nosuch\""), std::string::npos) << e;

  e = load_error(head + "[category.model]\nname = \"constant_gamma\"\n");  // missing gamma
  EXPECT_NE(e.find("gamma"), std::string::npos) << e;

  e = load_error(head + "[category.model]\nname = \"muhleman\"\nslope = 2\n");  // extra key
  EXPECT_NE(e.find("category[0].model.slope"), std::string::npos) << e;

  e = load_error(head +
                 "[category.model]\nname = \"oh1992\"\nrms_height = \"1 cm\"\n"
                 "permittivity = \"15 + 4j\"\n");
  EXPECT_NE(e.find("category[0].model.permittivity"), std::string::npos) << e;
  EXPECT_NE(e.find("wrong sign"), std::string::npos) << e;

  e = load_error(
      "[[category]]\nid = 1\nname = \"a\"\ncolour = \"red\"\n"
      "[category.model]\nname = \"muhleman\"\n");
  EXPECT_NE(e.find("category[0].colour"), std::string::npos) << e;

  e = load_error(head + "[category.model]\nname = \"muhleman\"\n" + head +
                 "[category.model]\nname = \"muhleman\"\n");
  EXPECT_NE(e.find("defined twice"), std::string::npos) << e;

  e = load_error(head);  // no model
  EXPECT_NE(e.find("category[0].model"), std::string::npos) << e;

  // Oh 1992 outside its ks range: 1 mm at 8.6 GHz is ks = 0.18 (fine); 0.1 mm is ks = 0.018.
  e = load_error(head +
                 "[category.model]\nname = \"oh1992\"\nrms_height = \"0.1 mm\"\n"
                 "permittivity = \"15 - 4j\"\n");
  EXPECT_NE(e.find("0.1 <= ks <= 6.0"), std::string::npos) << e;
  EXPECT_NE(e.find("category[0].model.rms_height"), std::string::npos) << e;
  // ... and allow_extrapolation turns that into a warning.
  e = load_error(head +
                 "allow_extrapolation = true\n[category.model]\nname = \"oh1992\"\n"
                 "rms_height = \"0.1 mm\"\npermittivity = \"15 - 4j\"\n");
  EXPECT_EQ(e, "");

  EXPECT_NE(load_error("x", "lib.txt").find("expected a category library"), std::string::npos);
}

TEST(Library, ShippedKuGeometricCoversTheTenCategoriesFromLToKuBand) {
  auto src = load_sigma0_source(default_sigma0_library_path());
  std::vector<std::uint16_t> ids;
  for (std::uint16_t i = 1; i <= 10; ++i) ids.push_back(i);
  EXPECT_EQ(src->category_ids(), ids);
  const char* names[] = {"wheat stubble", "tall alfalfa", "short alfalfa", "short corn",
                         "tall corn",     "short milo",   "tall milo",     "short soybeans",
                         "tall soybeans", "green wheat"};
  // (The display colours are checked against ris::category_colour() by
  // CategoryPalette.MatchesTheShippedCategoryLibraries.)
  for (std::uint16_t i = 1; i <= 10; ++i) EXPECT_EQ(src->category_name(i), names[i - 1]);
  // Every band from L to Ku, every polarisation: inside every component's
  // validity range (a range violation would throw here).
  for (double f : {1.0e9, 1.25e9, 3.2e9, 5.3e9, 8.6e9, 9.6e9, 13.5e9, 18.0e9}) {
    for (Polarisation p : {Polarisation::HH, Polarisation::VV, Polarisation::HV}) {
      const Sigma0Lut lut = Sigma0Lut::build(*src, RadarBand{f, p}, ids, "ku-geometric");
      for (std::uint16_t c : ids) EXPECT_TRUE(lut.has(c));
    }
  }
  // Outside 1-18 GHz the library refuses (its stated validity range).
  EXPECT_THROW(src->sigma0(5, 0.5, RadarBand{35e9, Polarisation::HH}), InputError);
  // A dense canopy approaches the water cloud's opaque limit A cos(t): tall corn
  // (W = 4.5 kg/m^2) at 8.6 GHz, 30 deg, within 0.3 dB of 0.228 cos 30 deg
  // (-7.05 dB; A from Attema & Ulaby 1978 as documented in the library).
  EXPECT_NEAR(db(src->sigma0(5, deg_to_rad(30.0), {8.6e9, Polarisation::HH})),
              db(0.228 * std::cos(deg_to_rad(30.0))), 0.3);
  // Cross-pol sits well below co-pol for every crop.
  for (std::uint16_t c : ids) {
    EXPECT_LT(src->sigma0(c, deg_to_rad(40.0), {5.3e9, Polarisation::HV}),
              0.5 * src->sigma0(c, deg_to_rad(40.0), {5.3e9, Polarisation::VV}));
  }
}

TEST(Library, ShippedGenericTerrainCoversIds20To27FromLToKuBand) {
  auto src =
      load_sigma0_source(std::string(ris::test::data_dir()) + "/backscatter/generic-terrain.toml");
  std::vector<std::uint16_t> ids;
  for (std::uint16_t i = 20; i <= 27; ++i) ids.push_back(i);
  EXPECT_EQ(src->category_ids(), ids);
  EXPECT_EQ(src->category_name(20), "bare soil");
  EXPECT_EQ(src->category_name(27), "snow");
  for (double f : {1.0e9, 1.25e9, 5.3e9, 9.6e9, 18.0e9}) {
    for (Polarisation p : {Polarisation::HH, Polarisation::VV, Polarisation::HV}) {
      const Sigma0Lut lut = Sigma0Lut::build(*src, RadarBand{f, p}, ids, "generic-terrain");
      for (std::uint16_t c : ids) EXPECT_TRUE(lut.has(c));
    }
  }
  // Smooth surfaces (water, road) are at least 5 dB darker than rough ones off nadir.
  const RadarBand x{9.6e9, Polarisation::VV};
  EXPECT_LT(src->sigma0(23, deg_to_rad(40.0), x), 0.316 * src->sigma0(22, deg_to_rad(40.0), x));
  EXPECT_LT(src->sigma0(25, deg_to_rad(40.0), x), 0.316 * src->sigma0(24, deg_to_rad(40.0), x));
}

// The LUT build asks for whole curves (sigma0_curve: band terms once, the
// water cloud's ground as a curve too); every shipped category gives exactly
// sigma0() at every angle of the table, L to Ku band, each polarisation.
TEST(Library, CurvesAreThePerAngleValuesExactly) {
  for (const char* file : {"ku-geometric.toml", "generic-terrain.toml"}) {
    auto src = load_sigma0_source(std::string(ris::test::data_dir()) + "/backscatter/" + file);
    std::vector<double> theta;
    for (int i = 0; i <= Sigma0Lut::kSteps; ++i)
      theta.push_back(std::min(i * Sigma0Lut::kStepRad, kPi / 2.0));
    for (double f : {1.25e9, 5.3e9, 9.6e9, 18.0e9}) {
      for (Polarisation p : {Polarisation::HH, Polarisation::VV, Polarisation::HV}) {
        const RadarBand band{f, p};
        for (std::uint16_t c : src->category_ids()) {
          std::vector<double> curve(theta.size());
          src->sigma0_curve(c, theta.data(), theta.size(), band, curve.data());
          for (std::size_t i = 0; i < theta.size(); ++i) {
            ASSERT_EQ(curve[i], src->sigma0(c, theta[i], band))
                << file << " category " << c << " " << f << " Hz, " << theta[i] << " rad";
          }
        }
      }
    }
  }
}

TEST(Library, ShippedTableMatchesTheLibraryItWasGeneratedFrom) {
  const std::string dir = std::string(ris::test::data_dir()) + "/backscatter/";
  auto lib = load_sigma0_source(dir + "ku-geometric.toml");
  auto table = load_sigma0_source(dir + "ku-geometric-8.6GHz.csv");
  for (std::uint16_t c = 1; c <= 10; ++c) {
    for (Polarisation p : {Polarisation::HH, Polarisation::VV}) {
      for (double deg = 0.0; deg <= 85.0; deg += 5.0) {
        const RadarBand band{8.6e9, p};
        // The table holds values rounded to 0.001 dB (ris sigma0 --format csv).
        EXPECT_NEAR(db(table->sigma0(c, deg_to_rad(deg), band)),
                    db(lib->sigma0(c, deg_to_rad(deg), band)), 0.001)
            << c << " " << to_string(p) << " " << deg;
      }
    }
  }
}

}  // namespace
}  // namespace ris
