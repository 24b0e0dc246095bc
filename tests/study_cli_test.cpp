// End-to-end: `ris study` on small hand-made inputs.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "ris/image/contact_sheet.h"
#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"
#include "ris/scene/scene_io.h"
#include "test_inputs.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::run_ris;
using test::TempDir;
using test::write_file;

// 60 rows x 200 columns of 10 m: rows 0-29 grass (1), rows 30-59 crop (2).
Scene two_blocks() {
  Scene s = Scene::flat(60, 200, 10.0, 0.0f, 1);
  for (int r = 30; r < 60; ++r) {
    for (int c = 0; c < 200; ++c) s.category[s.index(r, c)] = 2;
  }
  return s;
}

const std::string kRadar = test::kSmallSlarRadar;
const std::string kLibrary = test::constant_gamma_library(
    {{1, "grass", -12.0, "valid_frequency = [\"1 GHz\", \"18 GHz\"]\n"}, {2, "crop", -6.0, ""}},
    "two");

struct Inputs {
  TempDir dir;
  std::string scene = (dir / "scene.tif").string();
  std::string radar = (dir / "radar.toml").string();
  std::string library = (dir / "library.toml").string();
  Inputs() {
    write_scene_geotiff(two_blocks(), scene);
    write_file(radar, kRadar);
    write_file(library, kLibrary);
  }
  std::string args(const fs::path& out, const std::string& bands) const {
    return "study --scene " + scene + " --radar " + radar + " --backscatter " + library +
           " --out " + out.string() + " --bands '" + bands + "'";
  }
};

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

// The field `name` of a CSV row (no quoted commas in the fields read here).
std::string field(const std::string& header, const std::string& row, const std::string& name) {
  const auto split = [](const std::string& l) {
    std::vector<std::string> f;
    std::istringstream in(l);
    for (std::string x; std::getline(in, x, ',');) f.push_back(x);
    return f;
  };
  const auto h = split(header), r = split(row);
  for (std::size_t i = 0; i < h.size() && i < r.size(); ++i)
    if (h[i] == name) return r[i];
  return "(no field " + name + ")";
}

TEST(StudyCli, WritesPanelsSheetCsvAndMetadata) {
  const Inputs in;
  TempDir work;
  const fs::path out = work / "study";
  const auto r = run_ris(in.args(out, "1.25 GHz:HH, 8.6 GHz:VV, 13 GHz:HV"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("best band for telling the categories apart: "), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("null check (every category Muhleman's law): passed"), std::string::npos)
      << r.output;
  const std::vector<std::string> panels = {"panel_1_1.25GHz_HH.png", "panel_2_8.6GHz_VV.png",
                                           "panel_3_13GHz_HV.png"};
  for (const auto& f : panels) EXPECT_TRUE(fs::exists(out / f)) << f;

  // One row per (panel, category) and per (run, panel, pair), after a header.
  const auto cats = lines_of(read_file(out / "categories.csv"));
  ASSERT_EQ(cats.size(), 1u + 3u * 2u);
  EXPECT_EQ(cats[0].rfind("panel,band,frequency_ghz,polarisation,category,name,pixels", 0), 0u);
  EXPECT_EQ(cats[1].rfind("1,\"1.25 GHz HH\",1.25,HH,1,\"grass\",", 0), 0u) << cats[1];
  EXPECT_EQ(cats[6].rfind("3,\"13 GHz HV\",13,HV,2,\"crop\",", 0), 0u) << cats[6];
  const auto pairs = lines_of(read_file(out / "separability.csv"));
  ASSERT_EQ(pairs.size(), 1u + 3u * 2u);
  EXPECT_EQ(pairs[0].rfind("run,panel,band,category_a,name_a,category_b,name_b,bins,delta_db", 0),
            0u);
  // constant gamma -12 vs -6 dB in every band: calibrated sigma0 6 dB apart
  // (speckle's sampling error: 0.1 dB), separated; the null runs are not.
  for (std::size_t i = 1; i < pairs.size(); ++i) {
    const bool null = pairs[i].rfind("null,", 0) == 0;
    const double delta = std::stod(field(pairs[0], pairs[i], "delta_db"));
    EXPECT_NEAR(delta, null ? 0.0 : -6.0, 0.1) << pairs[i];
    EXPECT_EQ(field(pairs[0], pairs[i], "separated"), null ? "0" : "1") << pairs[i];
  }
  EXPECT_TRUE(fs::exists(out / "separability_bins.csv"));

  const nlohmann::json meta = nlohmann::json::parse(read_file(out / "metadata.json"));
  EXPECT_EQ(meta["bands"], nlohmann::json::array({"1.25 GHz HH", "8.6 GHz VV", "13 GHz HV"}));
  EXPECT_TRUE(meta["null_check"]["passed"].get<bool>());
  EXPECT_FALSE(meta["best_panel"].is_null());
  EXPECT_EQ(meta["verdict"].get<std::string>().rfind("best band: ", 0), 0u);
  ASSERT_EQ(meta["panels"].size(), 3u);
  EXPECT_EQ(meta["panels"][1]["simulation"]["inputs"]["radar"]["polarisation"], "VV");
  EXPECT_EQ(meta["panels"][1]["separability"]["separated_pairs"], 1);

  // The contact sheet: the layout of three panels of the panel size.
  const RasterF64 p = read_raster_f64(out / panels[0]);
  const std::vector<std::uint8_t> dummy(static_cast<std::size_t>(p.cols * p.rows));
  const ContactSheetLayout l = contact_sheet_layout(
      std::vector<ContactPanel>(3, ContactPanel{dummy.data(), p.cols, p.rows, ""}), {});
  const RasterF64 sheet = read_raster_f64(out / "contact_sheet.png");
  EXPECT_EQ(sheet.cols, l.width_px);
  EXPECT_EQ(sheet.rows, l.height_px);
  EXPECT_EQ(l.columns * l.rows, 3);
}

// The null check from the command line: one backscatter for both
// categories, no band named.
TEST(StudyCli, OneBackscatterForAllNamesNoBand) {
  Inputs in;
  write_file(in.library,
             test::constant_gamma_library({{1, "grass", -9.0, ""}, {2, "crop", -9.0, ""}}));
  TempDir work;
  const fs::path out = work / "study";
  const auto r = run_ris(in.args(out, "1.25 GHz:HH, 8.6 GHz:VV"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("no band separates these categories"), std::string::npos) << r.output;
  const nlohmann::json meta = nlohmann::json::parse(read_file(out / "metadata.json"));
  EXPECT_TRUE(meta["best_panel"].is_null());
  EXPECT_EQ(meta["verdict"], "no band separates these categories");
}

// A study file gives the inputs (relative to itself) and the window; the
// command line wins over it.
TEST(StudyCli, StudyFileGivesInputsAndWindow) {
  const Inputs in;
  const std::string study = (in.dir / "study.toml").string();
  write_file(study, R"([study]
name = "two blocks"
scene = "scene.tif"
radar = "radar.toml"
backscatter = "library.toml"
bands = "8.6 GHz:HH, 13 GHz:VV"
range_fraction = [0.25, 0.75]
incidence_bin = "0.5 deg"
)");
  TempDir work;
  const fs::path out = work / "study";
  const auto r = run_ris("study --study " + study + " --out " + out.string() +
                         " --no-null-check --bands '8.6 GHz:HH, 13 GHz:HH, 9 GHz:VV'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("two blocks: study of"), std::string::npos) << r.output;
  const nlohmann::json meta = nlohmann::json::parse(read_file(out / "metadata.json"));
  EXPECT_EQ(meta["bands"], nlohmann::json::array({"8.6 GHz HH", "13 GHz HH", "9 GHz VV"}));
  EXPECT_EQ(meta["method"]["window"]["range_fraction"], nlohmann::json::array({0.25, 0.75}));
  EXPECT_DOUBLE_EQ(meta["method"]["window"]["incidence_bin_deg"].get<double>(), 0.5);
  EXPECT_TRUE(meta["null_check"].is_null());

  // Bad windows: the file and key named, nothing written.
  const fs::path out2 = work / "bad";
  write_file(study, "[study]\nrange_fraction = [0.8, 0.2]\n");
  const auto bad = run_ris("study --study " + study + " --out " + out2.string());
  EXPECT_NE(bad.exit_code, 0);
  EXPECT_NE(bad.output.find("study.range_fraction"), std::string::npos) << bad.output;
  EXPECT_NE(bad.output.find("0 <= lo < hi <= 1"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(out2));
  const auto flag = run_ris(in.args(out2, "8.6 GHz:HH") + " --range-fraction 0.5");
  EXPECT_NE(flag.exit_code, 0);
  EXPECT_NE(flag.output.find("--range-fraction"), std::string::npos) << flag.output;
  write_file(study, "[study]\nwindow = 3\n");
  const auto unknown = run_ris("study --study " + study + " --out " + out2.string());
  EXPECT_NE(unknown.exit_code, 0);
  EXPECT_NE(unknown.output.find("window"), std::string::npos) << unknown.output;
  EXPECT_FALSE(fs::exists(out2));
}

TEST(StudyCli, BadBandListsFailWithoutOutput) {
  const Inputs in;
  TempDir work;
  const fs::path out = work / "study";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "empty band list"},
      {"8.6 GHz", "no polarisation"},
      {"8.6 GHz:HQ", "8.6 GHz:HQ"},
      {"8.6 GHz:HH, 8.6 GHz:HH", "duplicate band 8.6 GHz HH"},
      {"8.6 GHz:HH, 25 GHz:HH", "band 25 GHz HH is outside"},
  };
  for (const auto& [bands, message] : cases) {
    const auto r = run_ris(in.args(out, bands));
    EXPECT_NE(r.exit_code, 0) << bands;
    EXPECT_NE(r.output.find(message), std::string::npos) << bands << ": " << r.output;
    EXPECT_NE(r.output.find("--bands"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out)) << bands;
  }
  const auto r = run_ris(in.args(out, "8.6 GHz:HH, 25 GHz:HH"));
  EXPECT_NE(r.output.find("grass"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace ris
