#include "ris/backscatter/sigma0_table.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ris/util/error.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

using test::TempDir;
using test::write_file;

constexpr const char* kHeader = "category,frequency_ghz,polarisation,angle_deg,sigma0_db\n";

TEST(Sigma0Table, InterpolatesLinearlyInDb) {
  TempDir dir;
  write_file(dir / "t.csv", std::string("# category 3: corn\n") + kHeader +
                                "3,8.6,HH,10,-5\n3,8.6,HH,20,-9\n3,8.6,HH,40,-13\n"
                                "3,8.6,VV,10,-4\n3,8.6,VV,40,-10\n");
  const Sigma0Table t = Sigma0Table::load((dir / "t.csv").string());
  const auto* hh = t.find(3, RadarBand{8.6e9, Polarisation::HH});
  ASSERT_NE(hh, nullptr);
  // Halfway between 10 deg (-5 dB) and 20 deg (-9 dB): -7 dB exactly.
  EXPECT_NEAR(t.eval_db(*hh, deg_to_rad(15.0)), -7.0, 1e-12);
  // A quarter of the way from 20 (-9) to 40 (-13): -10 dB.
  EXPECT_NEAR(t.eval_db(*hh, deg_to_rad(25.0)), -10.0, 1e-12);
  EXPECT_NEAR(t.eval_db(*hh, deg_to_rad(40.0)), -13.0, 1e-12);
  EXPECT_EQ(t.name_of(3), "corn");
  EXPECT_EQ(t.find(3, RadarBand{9.0e9, Polarisation::HH}), nullptr);
  EXPECT_EQ(t.bands_of(3), "8.6 GHz HH, 8.6 GHz VV");
}

TEST(Sigma0Table, OutOfRangeAngleIsAnErrorUnlessClamped) {
  TempDir dir;
  write_file(dir / "t.csv", std::string(kHeader) + "1,8.6,HH,10,-5\n1,8.6,HH,40,-13\n");
  const Sigma0Table t = Sigma0Table::load((dir / "t.csv").string());
  const auto* c = t.find(1, RadarBand{8.6e9, Polarisation::HH});
  ASSERT_NE(c, nullptr);
  EXPECT_THROW(t.eval_db(*c, deg_to_rad(5.0)), InputError);
  EXPECT_THROW(t.eval_db(*c, deg_to_rad(41.0)), InputError);
  EXPECT_NEAR(t.eval_db(*c, deg_to_rad(5.0), true), -5.0, 1e-12);
  EXPECT_NEAR(t.eval_db(*c, deg_to_rad(60.0), true), -13.0, 1e-12);

  write_file(dir / "c.csv",
             std::string("# clamp: true\n") + kHeader + "1,8.6,HH,10,-5\n1,8.6,HH,40,-13\n");
  const Sigma0Table tc = Sigma0Table::load((dir / "c.csv").string());
  EXPECT_TRUE(tc.clamp());
  EXPECT_NEAR(tc.eval_db(tc.curves()[0], deg_to_rad(80.0)), -13.0, 1e-12);
}

TEST(Sigma0Table, NonIncreasingAnglesAreRejectedNamingTheLine) {
  TempDir dir;
  write_file(dir / "t.csv",
             std::string(kHeader) + "1,8.6,HH,10,-5\n1,8.6,HH,30,-9\n1,8.6,HH,30,-9\n");
  try {
    Sigma0Table::load((dir / "t.csv").string());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "line 4");
    EXPECT_NE(std::string(e.what()).find("angles must increase"), std::string::npos) << e.what();
  }
  write_file(dir / "d.csv", std::string(kHeader) + "1,8.6,HH,30,-5\n1,8.6,HH,20,-9\n");
  EXPECT_THROW(Sigma0Table::load((dir / "d.csv").string()), InputError);
}

TEST(Sigma0Table, MalformedFilesAreInputErrors) {
  TempDir dir;
  const auto bad = [&](const std::string& text) {
    write_file(dir / "b.csv", text);
    EXPECT_THROW(Sigma0Table::load((dir / "b.csv").string()), InputError) << text;
  };
  bad("cat,freq,pol,angle,s0\n1,8.6,HH,10,-5\n");                                  // wrong header
  bad(std::string(kHeader));                                                       // no rows
  bad(std::string(kHeader) + "1,8.6,XX,10,-5\n");                                  // polarisation
  bad(std::string(kHeader) + "1,8.6,HH,95,-5\n");                                  // angle > 90
  bad(std::string(kHeader) + "1,8.6,HH,10,abc\n");                                 // not a number
  bad(std::string(kHeader) + "1,8.6,HH,10\n");                                     // missing field
  bad(std::string(kHeader) + "0,8.6,HH,10,-5\n");                                  // category 0
  bad(std::string(kHeader) + "1,8.6,HH,10,-5\n2,8.6,HH,10,-5\n1,8.6,HH,20,-5\n");  // split curve
  EXPECT_THROW(Sigma0Table::load((dir / "missing.csv").string()), InputError);
}

}  // namespace
}  // namespace ris
