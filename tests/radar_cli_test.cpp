// End-to-end: `ris radar info` on the shipped radars and on a bad file.
#include <gtest/gtest.h>

#include <string>

#include "build_paths.h"
#include "test_util.h"

namespace ris {
namespace {

TEST(RadarCli, InfoPrintsTheSeedFigure45Numbers) {
  const test::RunResult r = test::run_ris("radar info");  // default: seed-fig4-5.toml
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("range bins                241"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("19.983 deg"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(109998 ft)"), std::string::npos) << r.output;
}

TEST(RadarCli, InfoShowsTheSarAndPpiParts) {
  const std::string dir = std::string(ris::test::data_dir()) + "/radars/";
  test::RunResult r = test::run_ris("radar info " + dir + "sar-x-band-stripmap.toml");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("mode                      sar,"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("(c / 2B, B = 20.0 MHz)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("2 x 2: pixel resolution 14.99 m x 15.00 m"), std::string::npos)
      << r.output;
  r = test::run_ris("radar info " + dir + "ppi-ground-mast-30m.toml");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("mode                      ppi,"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("rays every 0.500 deg (720 rays)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("30.0 m (98 ft) above the terrain"), std::string::npos) << r.output;
}

TEST(RadarCli, BadRadarFileFailsNamingFileAndKey) {
  test::TempDir dir;
  const auto path = dir / "bad.toml";
  test::write_file(path, R"(mode = "slar"
frequency = "8.6 GHz"
polarisation = "HX"
pulse_width = "0.1 us"
sweep_delay = "100 us"
sweep_length = "10 us"
azimuth_beamwidth = "1 mrad"
[track]
altitude = "5 km"
near_edge_distance = "10 km"
)");
  const test::RunResult r = test::run_ris("radar info " + path.string());
  EXPECT_EQ(r.exit_code, 1) << r.output;
  EXPECT_NE(r.output.find("bad.toml"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("polarisation"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace ris
