// End-to-end runs of `ris object rcs`.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "build_paths.h"
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

// tests/data/objects/two-objects.toml: one building facing the radar and
// one trihedral (src/sim/targets/object_centres_test.cpp checks the
// physics; here the command's products).
std::string town() {
  return std::string(test::test_data_dir()) + "/objects/two-objects.toml";
}

TEST(ObjectCli, SceneObjectsAreImagedAndReportedByteForByteOnAnyThreadCount) {
  TempDir dir;
  const std::string radar = std::string(test::data_dir()) + "/radars/sar-x-band-town.toml";
  std::string cmd = "simulate --quiet --scene " + q(town()) + " --radar " + q(radar) + " --out ";
  const auto one = run_ris(cmd + q(dir.path() / "t1") + " --threads 1");
  ASSERT_EQ(one.exit_code, 0) << one.output;
  const auto two = run_ris(cmd + q(dir.path() / "t2") + " --threads 2");
  ASSERT_EQ(two.exit_code, 0) << two.output;
  for (const char* f : {"mean_power_slant.tif", "speckled_power_slant.tif", "geocoded_power.tif"}) {
    EXPECT_EQ(test::read_file(dir.path() / "t1" / f), test::read_file(dir.path() / "t2" / f)) << f;
  }
  std::ifstream in(dir.path() / "t1" / "metadata.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  ASSERT_TRUE(m.contains("objects")) << m.dump(1);
  EXPECT_EQ(m["objects"]["objects"].get<int>(), 2);
  EXPECT_GT(m["objects"]["scattering_centres"].get<int>(), 1);
  EXPECT_FALSE(m.contains("point_targets")) << "object centres are not the user's targets";
  // The trihedral (a = 1 m, 9.6 GHz): 12 pi a^4 / lambda^2 = 45.9 dBsm.
  EXPECT_NEAR(m["objects"]["by_object"][1]["rcs_dbsm"].get<double>(), 45.9, 0.5);
  const auto info = run_ris("scene info " + q(town()));
  EXPECT_NE(info.output.find("1 buildings, 1 reflectors"), std::string::npos) << info.output;
}

TEST(ObjectCli, SceneObjectsRefusedWhereNotTracedNamingTheObject) {
  TempDir dir;
  const std::string ppi = std::string(test::data_dir()) + "/radars/ppi-ground-mast-30m.toml";
  const auto r = run_ris("simulate --quiet --scene " + q(town()) + " --radar " + q(ppi) +
                         " --out " + q(dir.path() / "o"));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("object[0] (building)"), std::string::npos) << r.output;
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "o" / "metadata.json"));
}

}  // namespace
}  // namespace ris
