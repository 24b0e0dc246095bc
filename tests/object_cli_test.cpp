// End-to-end runs of `ris object rcs`.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "test_util.h"

namespace ris {
namespace {

using test::q;
using test::run_ris;
using test::TempDir;

TEST(ObjectCli, TrihedralSweepWritesJsonNearTheClosedForm) {
  // Square trihedral, a = 0.2 m, 10 GHz: 12 pi a^4 / lambda^2 = 18.27 dBsm at
  // boresight (src/objects/sbr_test.cpp's error budget; 0.5 dB).
  TempDir dir;
  const auto out = dir.path() / "t.json";
  const auto r = run_ris(
      "object rcs --kind trihedral-square --size 0.2 -f '10 GHz' "
      "--azimuth -2:2:2 --out " +
      q(out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("M rays/s"), std::string::npos) << r.output;
  std::ifstream in(out);
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_EQ(j.size(), 3u);
  EXPECT_NEAR(j[1]["hh_dbsm"].get<double>(), 18.27, 0.5);
  EXPECT_NEAR(j[1]["vv_dbsm"].get<double>(), 18.27, 0.5);
}

TEST(ObjectCli, RefusesBadInputNamingTheOption) {
  const auto kind = run_ris("object rcs --kind cone --size 1");
  EXPECT_NE(kind.exit_code, 0);
  EXPECT_NE(kind.output.find("--kind"), std::string::npos) << kind.output;
  const auto both = run_ris("object rcs --size 1");
  EXPECT_NE(both.exit_code, 0);
  EXPECT_NE(both.output.find("--mesh"), std::string::npos) << both.output;
  const auto mat = run_ris("object rcs --kind plate --size 0.3 --material unobtainium");
  EXPECT_NE(mat.exit_code, 0);
  EXPECT_NE(mat.output.find("unobtainium"), std::string::npos) << mat.output;
  const auto band = run_ris("object rcs --kind plate --size 0.3 --material brick -f '60 GHz'");
  EXPECT_NE(band.exit_code, 0);
  EXPECT_NE(band.output.find("validity"), std::string::npos) << band.output;
  TempDir dir;
  test::write_file(dir.path() / "bad.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  const auto mesh = run_ris("object rcs --mesh " + q(dir.path() / "bad.obj"));
  EXPECT_NE(mesh.exit_code, 0);
  EXPECT_NE(mesh.output.find("degenerate"), std::string::npos) << mesh.output;
}

}  // namespace
}  // namespace ris
