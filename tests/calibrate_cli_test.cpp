// End-to-end: `ris calibrate` (docs/calibrate.md) on an image simulated
// with a known library recovers that library (issue 34's test: within
// 0.2 dB per category), writes a table `ris simulate --backscatter` reads,
// and refuses bad input naming it, leaving no output.
//
// The case: the Winnipeg UAVSAR product over its DEM (level ground, local
// incidence 19-37 deg), a land cover in UTM with category 1 (Muhleman's
// law) west of the image's middle and 2 (gamma = -12 dB, sigma0 = gamma cos t)
// east of it, and a small patch of category 3. The radar is the seed's
// figure-4-5 SLAR with N = 64 independent samples, so a bin of n >= 200
// pixels has a standard error of at most 4.34 / sqrt(64 x 200) = 0.038 dB
// (speckle), and 0.2 dB is over 5 standard errors. Without speckle the fit
// is within 0.03 dB of the library (measured), the residual of binning
// pixel-centre incidence against the elements'.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "acquisition_paths.h"
#include "refusal_checks.h"
#include "ris/backscatter/library.h"
#include "ris/geometry/topo.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/scene/geo_frame.h"
#include "ris/scene/scene_io.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

constexpr const char* kLibrary = R"(
[[category]]
id = 1
name = "muhleman"
colour = "#808080"
[category.model]
name = "muhleman"

[[category]]
id = 2
name = "gamma -12 dB"
colour = "#208020"
[category.model]
name = "constant_gamma"
gamma_db = -12

[[category]]
id = 3
name = "patch"
colour = "#a02020"
[category.model]
name = "muhleman"
)";

// The truth: Muhleman (MODEL.md section 4) and gamma cos t.
double truth_db(int category, double incidence_deg) {
  const double t = deg_to_rad(incidence_deg);
  if (category == 2) return -12.0 + 10.0 * std::log10(std::cos(t));
  return 10.0 * std::log10(0.0118 * std::cos(t) / std::pow(std::sin(t) + 0.111 * std::cos(t), 3.0));
}

struct Case {
  test::TempDir dir;
  fs::path cover, library, radar, sim;
  std::string acq;
};

// The land cover, library and radar files, and the simulated image.
const Case& the_case() {
  static Case* c = [] {
    auto* k = new Case;
    // The land cover's centre: the ground point of the image's middle pixel.
    const EllipsoidalDem dem = read_ellipsoidal_dem(test::test_dem("winnipeg_dem.tif"));
    const Acquisition acq = read_acquisition(test::winnipeg_h5());
    const GridWindow w = dem_window(acq, dem);
    std::vector<double> lat(w.bins), lon(w.bins);
    std::vector<float> f(7 * static_cast<std::size_t>(w.bins));
    std::vector<std::uint8_t> mask(w.bins);
    const auto fb = [&](int layer) { return f.data() + static_cast<std::size_t>(layer) * w.bins; };
    TopoLineScratch scratch;
    topo_radar_line(acq, dem, w, w.line0 + w.lines / 2,
                    {lat.data(), lon.data(), fb(0), fb(1), fb(2), fb(3), fb(4), fb(5), mask.data()},
                    scratch);
    const double lat_c = lat[w.bins / 2], lon_c = lon[w.bins / 2];
    Scene cover = Scene::flat(1000, 1000, 25.0, 0.0f, 1);
    cover.crs_wkt = utm_wkt_for(lon_c, lat_c);
    const auto [xc, yc] = GeoFrame(cover.crs_wkt, "test").scene_from_lonlat(lon_c, lat_c);
    cover.origin_x_m = xc - 12500.0;
    cover.origin_y_m = yc + 12500.0;
    for (int r = 0; r < cover.rows; ++r)
      for (int col = 500; col < cover.cols; ++col) cover.category[cover.index(r, col)] = 2;
    for (int r = 497; r < 500; ++r)
      for (int col = 494; col < 497; ++col) cover.category[cover.index(r, col)] = 3;
    k->cover = k->dir / "cover.tif";
    write_scene_geotiff(cover, k->cover);
    k->library = k->dir / "truth.toml";
    test::write_file(k->library, kLibrary);
    std::string radar = test::read_file(test::data("radars/seed-fig4-5.toml"));
    const std::string key = "independent_samples = \"seed\"";
    radar.replace(radar.find(key), key.size(), "independent_samples = 64");
    k->radar = k->dir / "r64.toml";
    test::write_file(k->radar, radar);
    k->acq = "-a " + test::winnipeg_h5() + " --dem " + test::q(test::test_dem("winnipeg_dem.tif"));
    k->sim = k->dir / "sim";
    const test::RunResult r = test::run_ris(
        "simulate --quiet " + k->acq + " --land-cover " + test::q(k->cover) + " --backscatter " +
        test::q(k->library) + " --radar " + test::q(k->radar) +
        " --calibrated --products beta0_slant,sigma0_slant_db --out " + test::q(k->sim));
    EXPECT_EQ(r.exit_code, 0) << r.output;
    return k;
  }();
  return *c;
}

std::string calibrate_args(const Case& c, const std::string& image, const fs::path& out) {
  return "calibrate " + test::q(image) + " " + c.acq + " --land-cover " + test::q(c.cover) +
         " --library " + test::q(c.library) + " --min-bin-pixels 200 --out " + test::q(out);
}

struct Row {
  int category = 0;
  double angle_deg = 0.0, db = 0.0;
};

// A written table's rows (the format of docs/backscatter.md).
std::vector<Row> read_table(const fs::path& table) {
  std::ifstream in(table);
  std::string line;
  std::vector<Row> rows;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("category,", 0) == 0) continue;
    Row r;
    double f = 0.0;
    char pol[3] = {0, 0, 0};
    EXPECT_EQ(
        std::sscanf(line.c_str(), "%d,%lf,%2c,%lf,%lf", &r.category, &f, pol, &r.angle_deg, &r.db),
        5)
        << line;
    rows.push_back(r);
  }
  return rows;
}

// Every row of the fitted table at or below max_angle_deg against the
// truth; counts the rows per category.
void expect_recovers_the_library(const fs::path& table, double tolerance_db,
                                 std::map<int, int>& rows, double max_angle_deg = 90.0) {
  for (const Row& r : read_table(table)) {
    if (r.angle_deg > max_angle_deg) continue;
    EXPECT_NEAR(r.db, truth_db(r.category, r.angle_deg), tolerance_db)
        << table << ": category " << r.category << " at " << r.angle_deg << " deg";
    ++rows[r.category];
  }
}

TEST(CalibrateCli, RecoversTheLibraryASimulationUsedWithin02DbPerCategory) {
  const Case& c = the_case();
  const fs::path out = c.dir / "fit.csv";
  const test::RunResult r =
      test::run_ris(calibrate_args(c, (c.sim / "beta0_slant.tif").string(), out));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // The patch (category 3) has too few pixels: named, and left out.
  EXPECT_THAT(r.output, ::testing::HasSubstr("warning: category 3 (patch): not fitted"));
  std::map<int, int> rows;
  expect_recovers_the_library(out, 0.2, rows);
  EXPECT_GE(rows[1], 10);
  EXPECT_GE(rows[2], 10);
  EXPECT_EQ(rows.count(3), 0u);
  // The summary: both categories' spread, the patch's reason.
  const nlohmann::json j = nlohmann::json::parse(test::read_file(c.dir / "fit.json"));
  ASSERT_EQ(j["categories"].size(), 3u);
  for (const auto& cat : j["categories"]) {
    if (cat["category"] == 3) {
      EXPECT_FALSE(cat["fitted"].get<bool>());
      continue;
    }
    EXPECT_TRUE(cat["fitted"].get<bool>());
    // 64-look speckle: the pixels' coefficient of variation is 1/8.
    for (const auto& b : cat["bins"]) EXPECT_NEAR(b["cv"].get<double>(), 0.125, 0.02);
    EXPECT_LT(cat["rms_residual_db"].get<double>(), 0.1);
  }
  EXPECT_EQ(j["frequency_ghz"].get<double>() > 1.2 && j["frequency_ghz"].get<double>() < 1.3, true);
  EXPECT_EQ(j["polarisation"], "HH");
}

// The same image as ellipsoid-referenced sigma0 in dB gives the same fit
// (on level ground sigma0_e sin(theta_l) / sin(theta_e) = sigma0_e); and
// the quadratic form is within the same tolerance.
TEST(CalibrateCli, Sigma0InDbAndTheQuadraticFormAgree) {
  const Case& c = the_case();
  const fs::path out = c.dir / "fit_db.csv";
  test::RunResult r =
      test::run_ris(calibrate_args(c, (c.sim / "sigma0_slant_db.tif").string(), out) +
                    " --quantity sigma0 --scale db --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  {
    std::map<int, int> rows;
    expect_recovers_the_library(out, 0.2, rows);
    EXPECT_EQ(rows.size(), 2u);
  }
  const fs::path quad = c.dir / "fit_quad.csv";
  r = test::run_ris(calibrate_args(c, (c.sim / "beta0_slant.tif").string(), quad) +
                    " --fit quadratic --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  {
    std::map<int, int> rows;
    expect_recovers_the_library(quad, 0.2, rows);
    EXPECT_EQ(rows.size(), 2u);
  }
}

// A table without the patch's category, used on a land cover without the
// patch: ris simulate reads it and the simulated calibrated image reads the
// fitted values back (a round trip through the written library).
TEST(CalibrateCli, TheWrittenTableIsALibraryRisSimulateReads) {
  const Case& c = the_case();
  const fs::path out = c.dir / "fit_rt.csv";
  test::RunResult r =
      test::run_ris(calibrate_args(c, (c.sim / "beta0_slant.tif").string(), out) + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path sim2 = c.dir / "sim2";
  r = test::run_ris("simulate --quiet " + c.acq + " --backscatter " + test::q(out) +
                    " --category 2 --radar " + test::q(c.radar) +
                    " --calibrated --products beta0_slant --out " + test::q(sim2));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const fs::path back = c.dir / "fit_back.csv";
  r = test::run_ris("calibrate " + test::q(sim2 / "beta0_slant.tif") + " " + c.acq +
                    " --category 2 --min-bin-pixels 200 --quiet --out " + test::q(back));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  // Within the first fit's angles the truth again; beyond them (category 2
  // covers more of the swath now) the table's end value, as clamp says.
  double last_angle = 0.0, last_db = 0.0;
  for (const Row& row : read_table(out)) {
    if (row.category == 2) last_angle = row.angle_deg, last_db = row.db;
  }
  std::map<int, int> rows;
  expect_recovers_the_library(back, 0.2, rows, last_angle);
  EXPECT_EQ(rows.size(), 1u);
  EXPECT_GE(rows[2], 10);
  int beyond = 0;
  for (const Row& row : read_table(back)) {
    if (row.angle_deg <= last_angle + 0.5) continue;  // bins straddling the end
    EXPECT_NEAR(row.db, last_db, 0.2) << "at " << row.angle_deg << " deg";
    ++beyond;
  }
  EXPECT_GE(beyond, 2);
}

// On relief: the San Andreas UAVSAR product over its DEM (local incidence
// 37-50 deg across slopes), one category. The area normalisation
// sigma0 = beta0 sin(theta_l) recovers Muhleman's law within 0.2 dB in every
// bin of 500 or more pixels (measured: 0.11 dB at worst, in the tails of
// the incidence distribution, where a pixel's power averages facets less
// extreme than its centre's; 0.14 dB without speckle).
TEST(CalibrateCli, RecoversTheLibraryOnRelief) {
  const Case& c = the_case();
  test::TempDir dir;
  const std::string sanand =
      "-a " + test::sanand_h5() + " --dem " + test::q(test::test_dem("SanAnd_dem.tif"));
  test::RunResult r =
      test::run_ris("simulate --quiet " + sanand + " --backscatter " + test::q(c.library) +
                    " --category 1 --radar " + test::q(c.radar) +
                    " --calibrated --products beta0_slant --out " + test::q(dir / "sim"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_ris("calibrate " + test::q(dir / "sim" / "beta0_slant.tif") + " " + sanand +
                    " --min-bin-pixels 500 --quiet --out " + test::q(dir / "fit.csv"));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::map<int, int> rows;
  expect_recovers_the_library(dir / "fit.csv", 0.2, rows);
  EXPECT_GE(rows[1], 8);
}

// --append adds another polarisation's curves to a table; a curve the table
// has already is refused naming --append, and the table stays as it was.
TEST(CalibrateCli, AppendAddsAPolarisationAndRefusesACurveTwice) {
  const Case& c = the_case();
  test::TempDir dir;
  const std::string beta0 = (c.sim / "beta0_slant.tif").string();
  const fs::path out = dir / "lib.csv";
  test::RunResult r = test::run_ris(calibrate_args(c, beta0, out) + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  r = test::run_ris(calibrate_args(c, beta0, out) + " --append --polarisation VV --summary " +
                    test::q(dir / "vv.json") + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const std::string table = test::read_file(out);
  int hh = 0, vv = 0;
  for (std::size_t at = table.find(",HH,"); at != std::string::npos;
       at = table.find(",HH,", at + 1))
    ++hh;
  for (std::size_t at = table.find(",VV,"); at != std::string::npos;
       at = table.find(",VV,", at + 1))
    ++vv;
  EXPECT_GT(hh, 20);
  EXPECT_EQ(hh, vv);
  const auto lib = load_sigma0_source(out.string());
  const RadarBand vv_band{1.243e9, Polarisation::VV};
  EXPECT_NO_THROW(lib->sigma0(2, deg_to_rad(25.0), vv_band));
  const std::set<std::string> before = test::listing(dir.path());
  r = test::run_ris(calibrate_args(c, beta0, out) + " --append --polarisation VV --summary " +
                    test::q(dir / "vv2.json"));
  test::expect_refused(r, 1, "--append", dir.path(), before);
  EXPECT_EQ(test::read_file(out), table);
  r = test::run_ris(calibrate_args(c, beta0, dir / "none.csv") + " --append --summary " +
                    test::q(dir / "x.json"));
  test::expect_refused(r, 1, "no table to append to", dir.path(), before);
}

TEST(CalibrateCli, BadInputIsRefusedNamingItAndLeavesNoOutput) {
  const Case& c = the_case();
  test::TempDir dir;
  // A raster of another grid.
  Scene small = Scene::flat(40, 30, 25.0, 1.0f, 1);
  write_scene_geotiff(small, dir / "small.tif");
  const std::set<std::string> before = test::listing(dir.path());
  const auto refused = [&](const std::string& args, const std::string& text) {
    const test::RunResult r = test::run_ris(args);
    test::expect_refused(r, 1, text, dir.path(), before);
  };
  const std::string beta0 = (c.sim / "beta0_slant.tif").string();
  refused(calibrate_args(c, (dir / "small.tif").string(), dir / "o.csv"), "30 x 40 pixels");
  refused(calibrate_args(c, (dir / "missing.tif").string(), dir / "o.csv"), "missing.tif");
  refused("calibrate " + test::q(beta0) + " " + c.acq + " --land-cover " +
              test::q(dir / "nocover.tif") + " --out " + test::q(dir / "o.csv"),
          "nocover.tif");
  // A land cover without a CRS cannot be placed on the ground points.
  refused("calibrate " + test::q(beta0) + " " + c.acq + " --land-cover " +
              test::q(dir / "small.tif") + " --out " + test::q(dir / "o.csv"),
          "the land cover has no CRS");
  // Every category below its pixel count: the error names it, nothing written.
  const test::RunResult few =
      test::run_ris(calibrate_args(c, beta0, dir / "o.csv") + " --min-pixels 100000000");
  test::expect_refused(few, 1, "no category could be fitted", dir.path(), before);
  EXPECT_THAT(few.output, ::testing::HasSubstr("warning: category 1 (muhleman): not fitted"));
  // A dB image read as power.
  refused(calibrate_args(c, (c.sim / "sigma0_slant_db.tif").string(), dir / "o.csv"), "--scale db");
  refused(calibrate_args(c, beta0, dir / "o.txt"), "--out");
  refused(calibrate_args(c, beta0, dir / "o.csv") + " --quantity gamma0", "--quantity");
}

}  // namespace
}  // namespace ris
