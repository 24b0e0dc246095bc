// End-to-end runs of `ris sigma0`.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>

#include "ris/backscatter/library.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

using test::run_ris;
using test::TempDir;

const std::string kOh =
    "--model 'name = \"oh1992\", rms_height = \"1 cm\", permittivity = \"15 - 4j\"'";

TEST(Sigma0Cli, InlineModelTablePrintsTheIssueFourOhValues) {
  // Oh 1992, eps = 15 - 4j, 5.405 GHz, s = 1 cm, 30 deg: HH -7.96, VV -6.89,
  // HV -17.19 dB (ris issue 4).
  const auto r = run_ris("sigma0 " + kOh + " -f '5.405 GHz' -p HH,VV,HV -a 30");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("-7.96"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("-6.89"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("-17.19"), std::string::npos) << r.output;
}

TEST(Sigma0Cli, JsonHasOneSeriesPerCategoryAndPolarisation) {
  const auto r = run_ris("sigma0 --category '4,tall corn' -p HH,VV -a 0:60:30 --format json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  ASSERT_EQ(j.size(), 4u);
  EXPECT_EQ(j[0]["category"], 4);
  EXPECT_EQ(j[0]["name"], "short corn");
  EXPECT_EQ(j[0]["polarisation"], "HH");
  EXPECT_EQ(j[3]["name"], "tall corn");
  EXPECT_EQ(j[3]["angle_deg"].size(), 3u);
  EXPECT_DOUBLE_EQ(j[0]["frequency_ghz"].get<double>(), 8.6);
}

TEST(Sigma0Cli, CsvOutputIsATableFileThatReproducesTheLibrary) {
  TempDir dir;
  const std::string csv = (dir / "t.csv").string();
  const auto r = run_ris("sigma0 --category 2,9 -p VV -a 0:90:1 --format csv --out " + csv);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  auto table = load_sigma0_source(csv);
  auto lib = load_sigma0_source(default_sigma0_library_path());
  EXPECT_EQ(table->category_name(9), "tall soybeans");
  const RadarBand band{8.6e9, Polarisation::VV};
  for (double deg : {0.0, 12.5, 45.0, 71.3}) {
    // Linear in dB between 1-deg samples of a smooth curve: within 0.01 dB.
    EXPECT_NEAR(10 * std::log10(table->sigma0(9, deg_to_rad(deg), band)),
                10 * std::log10(lib->sigma0(9, deg_to_rad(deg), band)), 0.01)
        << deg;
  }
}

TEST(Sigma0Cli, PlotWritesAPng) {
  TempDir dir;
  const std::string png = (dir / "s0.png").string();
  const auto r = run_ris("sigma0 -a 0:80:2 -p HH,VV --plot " + png);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string bytes = test::read_file(png);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
}

TEST(Sigma0Cli, BadInputExitsNonZeroNamingTheProblem) {
  auto r = run_ris("sigma0 --model 'name = \"nosuch\"'");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("unknown backscatter model"), std::string::npos) << r.output;
  r = run_ris("sigma0 " + kOh + " -a 95");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--angles"), std::string::npos) << r.output;
  r = run_ris("sigma0 --library /no/such/lib.toml");
  EXPECT_EQ(r.exit_code, 1);
  r = run_ris("sigma0 --category 99");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("no category \"99\""), std::string::npos) << r.output;
  r = run_ris("sigma0 -f '35 GHz'");  // outside the crop library's 1-18 GHz
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("1..18 GHz"), std::string::npos) << r.output;
  r = run_ris("sigma0 " + kOh + " -p XX");
  EXPECT_EQ(r.exit_code, 1);
  TempDir dir;
  // 0.3 GHz: ks = 0.063 < 0.1, outside Oh 1992's range: refused before any output.
  r = run_ris("sigma0 " + kOh + " -f '0.3 GHz' --plot " + (dir / "x.png").string() + " --out " +
              (dir / "x.txt").string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_FALSE(std::filesystem::exists(dir / "x.txt"));
  EXPECT_FALSE(std::filesystem::exists(dir / "x.png"));  // nothing half-written
}

}  // namespace
}  // namespace ris
