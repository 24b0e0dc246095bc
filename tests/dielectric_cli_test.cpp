// End-to-end runs of `ris dielectric`.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

#include "ris/backscatter/dielectric.h"
#include "test_util.h"

namespace ris {
namespace {

using test::run_ris;
using test::TempDir;

TEST(DielectricCli, TablePrintsPublishedAndHandComputedValues) {
  // Hallikainen et al. (1985) Table V by hand, sand 30.6 %, clay 13.5 %,
  // mv = 0.2, 1.4 GHz: 9.6657 - 1.9597j (src/backscatter/dielectric/
  // dielectric_test.cpp); the table prints two decimals.
  const auto r = run_ris(
      "dielectric --model hallikainen1985 --moisture 0.2 -f '1.4 GHz' --clay 0.135 --sand 0.306");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("9.67 - 1.96j"), std::string::npos) << r.output;
}

TEST(DielectricCli, JsonHasOneSeriesPerModelAndFrequencyAndNeedsNoSandForMironov) {
  // Mironov et al. (2009), mv = 0.25, clay 30 %, 5.405 GHz: 11.24897 - 2.52547j
  // (the reference implementation's value, dielectric_test.cpp), within 1e-3.
  const auto r = run_ris(
      "dielectric --model mironov2009 --moisture 0.1,0.25 -f '1.4 GHz,5.405 GHz' --clay 0.3 "
      "--sand 0 --format json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  ASSERT_EQ(j.size(), 2u);
  EXPECT_EQ(j[1]["model"], "mironov2009");
  EXPECT_DOUBLE_EQ(j[1]["frequency_ghz"].get<double>(), 5.405);
  EXPECT_NEAR(j[1]["eps_real"][1].get<double>(), 11.24897, 1e-3);
  EXPECT_NEAR(j[1]["eps_imag"][1].get<double>(), 2.52547, 1e-3);
}

TEST(DielectricCli, DobsonConductivityIsSelectable) {
  // dielectric_test.cpp's loam at mv 0.3, 1.4 GHz: eps'' 2.56076 with Dobson's
  // conductivity fit, 1.53288 with Peplinski's; eps' 16.87544 with both.
  const std::string soil =
      "dielectric --model dobson1985 --moisture 0.3 -f '1.4 GHz' --clay 0.135 --sand 0.306 "
      "--format json";
  const auto d = run_ris(soil);
  const auto p = run_ris(soil + " --conductivity peplinski1995");
  ASSERT_EQ(d.exit_code, 0) << d.output;
  ASSERT_EQ(p.exit_code, 0) << p.output;
  const nlohmann::json jd = nlohmann::json::parse(d.output);
  const nlohmann::json jp = nlohmann::json::parse(p.output);
  EXPECT_EQ(jd[0]["dobson_conductivity"], "dobson1985");
  EXPECT_EQ(jp[0]["dobson_conductivity"], "peplinski1995");
  EXPECT_NEAR(jd[0]["eps_imag"][0].get<double>(), 2.56076, 1e-4);
  EXPECT_NEAR(jp[0]["eps_imag"][0].get<double>(), 1.53288, 1e-4);
  EXPECT_DOUBLE_EQ(jd[0]["eps_real"][0].get<double>(), jp[0]["eps_real"][0].get<double>());
  const auto bad = run_ris(soil + " --conductivity ohm");
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("--conductivity"), std::string::npos) << bad.output;
}

TEST(DielectricCli, CsvAndPlotAreWritten) {
  TempDir dir;
  const std::string csv = (dir / "eps.csv").string();
  const std::string png = (dir / "eps.png").string();
  const auto r = run_ris("dielectric --model all --moisture 0.05:0.45:0.1 --format csv --out " +
                         csv + " --plot " + png);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string text = test::read_file(csv);
  EXPECT_NE(text.find("model,frequency_ghz,moisture_m3_m3,eps_real,eps_imag"), std::string::npos);
  EXPECT_NE(text.find("dobson1985,5.3,0.05,"), std::string::npos) << text;
  EXPECT_NE(text.find("mironov2009,5.3,0.45,"), std::string::npos) << text;
  const std::string bytes = test::read_file(png);
  ASSERT_GT(bytes.size(), 1000u);
  EXPECT_EQ(bytes.substr(1, 3), "PNG");
}

TEST(DielectricCli, ListsTheRegistrysModels) {
  // `--model all` and the message for an unknown model name the library's
  // registry (ris/backscatter/dielectric.h), in its order.
  const auto r = run_ris("dielectric --model all --moisture 0.2 --format json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::vector<std::string> listed;
  for (const auto& series : nlohmann::json::parse(r.output)) listed.push_back(series["model"]);
  std::vector<std::string> registry;
  for (std::string_view n : dielectric_model_names()) registry.emplace_back(n);
  EXPECT_EQ(listed, registry);
  const auto bad = run_ris("dielectric --model topp1980");
  EXPECT_NE(bad.output.find("(known: " + joined_names(dielectric_model_names()) + ", or all)"),
            std::string::npos)
      << bad.output;
}

TEST(DielectricCli, BadInputExitsNonZeroNamingTheProblem) {
  auto r = run_ris("dielectric --model topp1980");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("unknown dielectric model \"topp1980\""), std::string::npos) << r.output;
  r = run_ris("dielectric --model dobson1985 -f '30 GHz'");  // Dobson: 1.4-18 GHz
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("[1.4, 18] GHz"), std::string::npos) << r.output;
  r = run_ris("dielectric --model dobson1985 -f '30 GHz' --allow-extrapolation");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  r = run_ris("dielectric --moisture 0.3:0.1:0.05");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("--moisture"), std::string::npos) << r.output;
  r = run_ris("dielectric --clay 0.7 --sand 0.5");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.output.find("clay + sand"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace ris
