// The calibration test of issue 20: every generic-terrain category that has a
// class in Ulaby & Dobson's handbook is within 1 dB of that class's measured
// mean curve at 20-60 deg, HH/HV/VV, at each band it claims.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "build_paths.h"
#include "ris/backscatter/backscatter_model.h"
#include "ris/backscatter/library.h"
#include "ris/io/config_table.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

double db(double x) {
  return 10.0 * std::log10(x);
}

std::unique_ptr<BackscatterModel> handbook_class(const std::string& terrain) {
  static std::vector<toml::table> keep;  // the ConfigTable refers to its table
  keep.push_back(toml::parse("m = { name = \"ulaby_dobson\", terrain = \"" + terrain + "\" }"));
  ConfigTable root(keep.back(), "test.toml", "");
  std::optional<ConfigTable> t = root.subtable("m");
  return make_backscatter_model(*t, ModelContext{"test.toml", ".", false, -1, nullptr});
}

TEST(LibraryCalibration, GenericTerrainIsWithinOneDbOfItsHandbookClass) {
  auto lib =
      load_sigma0_source(std::string(ris::test::data_dir()) + "/backscatter/generic-terrain.toml");
  struct Claim {
    std::uint16_t id;
    const char* terrain;
    std::vector<double> bands_hz;  // one frequency in each band claimed
  };
  const double kL = 1.25e9;
  const double kS = 3.2e9;
  const double kC = 5.3e9;
  const Claim claims[] = {{20, "soil", {kL, kS, kC}},
                          {21, "grass", {kL, kS, kC}},
                          {22, "shrubs", {kL, kC}},
                          {27, "dry_snow", {kL, kS, kC}}};
  for (const Claim& c : claims) {
    auto ref = handbook_class(c.terrain);
    for (double f : c.bands_hz) {
      for (Polarisation p : {Polarisation::HH, Polarisation::HV, Polarisation::VV}) {
        const RadarBand band{f, p};
        for (double deg = 20.0; deg <= 60.0; deg += 5.0) {
          const double t = deg_to_rad(deg);
          EXPECT_NEAR(db(lib->sigma0(c.id, t, band)), db(ref->sigma0(t, band)), 1.0)
              << lib->category_name(c.id) << " vs " << c.terrain << " at " << f / 1e9 << " GHz "
              << to_string(p) << " " << deg << " deg";
        }
      }
    }
  }
}

// `ris sigma0 --library data/backscatter/ulaby-dobson-1989.toml` resolves
// every handbook class at L, S and C band (shrubs: L and C; its S rows are not
// shipped), each equal to the class's ulaby_dobson model.
TEST(LibraryCalibration, HandbookLibraryResolvesEveryClassAtLSAndC) {
  // Every class at L, S and C band (shrubs not at S); trees at X band only.
  auto lib = load_sigma0_source(std::string(ris::test::data_dir()) +
                                "/backscatter/ulaby-dobson-1989.toml");
  const char* classes[] = {"soil", "grass", "short_vegetation", "shrubs", "dry_snow", "wet_snow"};
  ASSERT_EQ(lib->category_ids().size(), 7u);  // and trees (46), X band only
  for (double f : {1.25e9, 3.2e9, 5.3e9, 13e9}) {
    EXPECT_THROW(lib->sigma0(46, deg_to_rad(30.0), {f, Polarisation::HH}), InputError) << f;
  }
  EXPECT_EQ(lib->sigma0(46, deg_to_rad(30.0), {9.6e9, Polarisation::HV}),
            handbook_class("trees")->sigma0(deg_to_rad(30.0), {9.6e9, Polarisation::HV}));
  for (std::uint16_t id = 40; id <= 45; ++id) {
    auto ref = handbook_class(classes[id - 40]);
    for (double f : {1.25e9, 3.2e9, 5.3e9}) {
      for (Polarisation p : {Polarisation::HH, Polarisation::HV, Polarisation::VV}) {
        const RadarBand band{f, p};
        if (id == 43 && f == 3.2e9) {
          EXPECT_THROW(lib->sigma0(id, deg_to_rad(30.0), band), InputError);
          continue;
        }
        EXPECT_EQ(lib->sigma0(id, deg_to_rad(30.0), band), ref->sigma0(deg_to_rad(30.0), band))
            << id << " " << f;
      }
    }
  }
}

}  // namespace
}  // namespace ris
