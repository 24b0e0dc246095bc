// The frequency/polarisation study: band lists, category attribution,
// the choice of band, and a synthetic scene whose best band is known by
// construction.
#include "ris/analysis/study.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <string>

#include "build_paths.h"
#include "ris/analysis/study_config.h"
#include "ris/backscatter/library.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

using test::TempDir;
using test::write_file;

template <typename F>
std::string input_error(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no InputError)";
}

TEST(StudyBands, ParsesAListWithUnitsAndSpaces) {
  const auto b = parse_study_bands(" 1.25 GHz:HH,8600 MHz : vv , 13 GHz:HV", "--bands");
  ASSERT_EQ(b.size(), 3u);
  EXPECT_DOUBLE_EQ(b[0].frequency_hz, 1.25e9);
  EXPECT_EQ(b[0].polarisation, Polarisation::HH);
  EXPECT_DOUBLE_EQ(b[1].frequency_hz, 8.6e9);
  EXPECT_EQ(b[1].polarisation, Polarisation::VV);
  EXPECT_EQ(b[2].polarisation, Polarisation::HV);
  EXPECT_EQ(b[1].label(), "8.6 GHz VV");
  EXPECT_EQ(b[1].slug(), "8.6GHz_VV");
}

TEST(StudyBands, DefaultListIsSixBandsInsideTheStandardLibrary) {
  const auto b = default_study_bands();
  ASSERT_EQ(b.size(), 6u);
  // The two the seed's figure 7 names.
  EXPECT_NE(std::find(b.begin(), b.end(), StudyBand{8.6e9, Polarisation::HH}), b.end());
  EXPECT_NE(std::find(b.begin(), b.end(), StudyBand{8.6e9, Polarisation::VV}), b.end());
  for (const StudyBand& x : b) {
    EXPECT_GE(x.frequency_hz, 1e9);
    EXPECT_LE(x.frequency_hz, 18e9);
  }
}

TEST(StudyBands, BadListsAreInputErrorsNamingTheOption) {
  for (const char* bad : {"", "   ", "8.6 GHz", "8.6 GHz:XX", "fast:HH", "8.6 GHz:HH,",
                          ",8.6 GHz:HH", "-1 GHz:HH", "0 GHz:VV", "8.6 parsecs:HH"}) {
    EXPECT_THROW(parse_study_bands(bad, "--bands"), InputError) << bad;
  }
  const std::string dup =
      input_error([] { parse_study_bands("8.6 GHz:HH, 8600 MHz:hh", "--bands"); });
  EXPECT_NE(dup.find("duplicate band 8.6 GHz HH"), std::string::npos) << dup;
  EXPECT_NE(input_error([] { parse_study_bands("", "--bands"); }).find("--bands"),
            std::string::npos);
}

TEST(StudyContrast, CategoryStatsOverAttributedPixelsOnly) {
  const std::vector<std::int32_t> labels{1, 1, -1, 2, 2, 2, 7};
  const std::vector<std::uint8_t> grey{10, 20, 200, 50, 50, 80, 90};
  const std::vector<float> power{1, 3, 100, 2, 2, 2, 5};
  const auto s = category_stats(labels, grey, power, {1, 2, 4}, {"a", "b", "d"});
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].pixels, 2);
  EXPECT_DOUBLE_EQ(s[0].mean_grey, 15.0);
  EXPECT_DOUBLE_EQ(s[0].std_grey, 5.0);
  EXPECT_DOUBLE_EQ(s[0].mean_power_w, 2.0);
  EXPECT_EQ(s[1].pixels, 3);
  EXPECT_DOUBLE_EQ(s[1].mean_grey, 60.0);
  EXPECT_EQ(s[2].pixels, 0);  // reported, empty
  EXPECT_TRUE(std::isnan(s[2].mean_grey));
}

TEST(StudyContrast, ChoosesThePanelOfLargestScoreOrNone) {
  StudyResult r;
  r.panels.resize(3);
  r.panels[0].separability.score = 0.2;
  r.panels[1].separability.score = 0.7;
  r.panels[2].separability.score = 0.0;
  r.null_check_run = true;
  r.panels[2].null_separability.max_abs_z = 2.5;
  choose_best(r);
  EXPECT_EQ(r.best_panel, 1);
  EXPECT_TRUE(r.null_check_passed);
  EXPECT_DOUBLE_EQ(r.null_max_abs_z, 2.5);
  // No separated pair anywhere: no best band.
  for (StudyPanel& p : r.panels) p.separability.score = 0.0;
  r.panels[0].null_separability.separated_pairs = 1;
  choose_best(r);
  EXPECT_EQ(r.best_panel, -1);
  EXPECT_FALSE(r.null_check_passed);
}

// A flat scene of three azimuth blocks (30 rows each): categories 1, 2, 3.
// Every block spans the whole swath, so each category sees the same ranges
// and incidences and only sigma0 differs.
Scene three_blocks() {
  Scene s = Scene::flat(90, 200, 10.0, 0.0f, 1);
  for (int r = 0; r < 90; ++r) {
    for (int c = 0; c < 200; ++c)
      s.category[s.index(r, c)] = static_cast<std::uint16_t>(1 + r / 30);
  }
  return s;
}

// Fading off, so greytones are deterministic; gamma 0.4 keeps a 6 dB step
// inside the grey scale.
const char* kRadar = R"(
mode = "slar"
frequency = "9.4 GHz"
polarisation = "HH"
pulse_width = "0.1 us"
sweep_delay = "33.4 us"
sweep_length = "10 us"
azimuth_beamwidth = "5 mrad"
[track]
altitude = "3000 m"
near_edge_distance = "4000 m"
[film]
gamma = 0.4
[film.terms]
fading = false
)";

// Known contrast per band (constant gamma, dB): grass -10 everywhere, soil -9
// everywhere, crop -10 at L band, -4 at X band (8-9 GHz), -9.5 at Ku band
// (12-14 GHz). Pairs (grass, crop, soil) in dB: L 0/1/1, X 6/5/1, Ku 0.5/0.5/1;
// X band separates best.
const char* kLibrary = R"(
[library]
name = "three"
[[category]]
id = 1
name = "grass"
colour = "#30a030"
[category.model]
name = "constant_gamma"
gamma_db = -10.0
valid_frequency = ["1 GHz", "18 GHz"]
[[category]]
id = 2
name = "crop"
colour = "#a0a030"
[category.model]
name = "constant_gamma"
gamma_db = -10.0
[[category.band]]
frequency = ["8 GHz", "9 GHz"]
[category.band.model]
name = "constant_gamma"
gamma_db = -4.0
[[category.band]]
frequency = ["12 GHz", "14 GHz"]
[category.band.model]
name = "constant_gamma"
gamma_db = -9.5
[[category]]
id = 3
name = "soil"
colour = "#a06030"
[category.model]
name = "constant_gamma"
gamma_db = -9.0
)";

// The same radar with exact gamma fading, for the separability tests.
std::string with_fading(std::string radar) {
  const std::string off = "[film.terms]\nfading = false\n";
  radar.replace(radar.find(off), off.size(), "fading = \"exact\"\n");
  return radar;
}

struct Synthetic {
  TempDir dir;
  std::string library = (dir / "three.toml").string();
  RadarParams radar = radar_from_toml(toml::parse(kRadar), "radar.toml");
  RadarParams speckled = radar_from_toml(toml::parse(with_fading(kRadar)), "radar.toml");
  Synthetic() { write_file(library, kLibrary); }
};

TEST(Study, SyntheticSceneTheKnownBandWins) {
  const Synthetic in;
  const auto sigma0 = load_sigma0_source(in.library);
  const Scene scene = three_blocks();
  const auto bands = parse_study_bands("1.25 GHz:HH, 8.6 GHz:HH, 13 GHz:HH", "--bands");
  const StudyResult r = run_study(scene, in.speckled, *sigma0, in.library, bands);
  ASSERT_EQ(r.panels.size(), 3u);
  EXPECT_EQ(r.categories, (std::vector<std::uint16_t>{1, 2, 3}));
  EXPECT_EQ(r.best_panel, 1);

  // Calibrated sigma0 at matched geometry: the ratio of the categories'
  // sigma0 (dB, a over b), within the speckle's sampling error.
  const std::map<std::pair<int, int>, std::array<double, 3>> expected_db{
      {{1, 2}, {0.0, -6.0, -0.5}}, {{1, 3}, {-1.0, -1.0, -1.0}}, {{2, 3}, {-1.0, 5.0, -0.5}}};
  for (std::size_t i = 0; i < 3; ++i) {
    const StudyPanel& p = r.panels[i];
    ASSERT_EQ(p.separability.pairs.size(), 3u);
    ASSERT_EQ(p.stats.size(), 3u);
    for (const PairSeparability& c : p.separability.pairs) {
      const double want = expected_db.at({c.a, c.b})[i];
      // Within 4 standard errors (sigma_dB = delta_db / z; L band has 1.5
      // looks, X band 10).
      const double sigma_db = std::abs(c.delta_db / c.z);
      EXPECT_LT(std::abs(c.delta_db - want), 4.0 * sigma_db + 1e-3)
          << p.band.label() << " " << c.a << "/" << c.b;
      EXPECT_LT(sigma_db, 0.2) << p.band.label();
      // A difference of 0.5 dB or more is far beyond the sampling error here.
      EXPECT_EQ(c.separated, std::abs(want) >= 0.5) << p.band.label() << " " << c.a << "/" << c.b;
    }
    // Every block loses its footprint's reach at both ends (a category
    // boundary or the track's end): equal counts, fewer than 28 lines' worth.
    EXPECT_EQ(p.stats[0].pixels, p.stats[2].pixels);
    EXPECT_EQ(p.stats[1].pixels, p.stats[0].pixels);
    EXPECT_GT(p.stats[1].pixels, 20 * p.bins / 2);
    EXPECT_LE(p.stats[1].pixels, 28 * p.bins);
    EXPECT_EQ(static_cast<int>(p.slant_grey.size()), p.lines * p.bins);
  }
  // At X band crop is told from both others by more than they from each other.
  const auto& x = r.panels[1].separability.pairs;
  EXPECT_GT(x[0].jm, x[1].jm);
  EXPECT_GT(x[2].jm, x[1].jm);
}

TEST(Study, AttributionLeavesBlockBoundariesOut) {
  const Synthetic in;
  const auto sigma0 = load_sigma0_source(in.library);
  const Scene scene = three_blocks();
  const RadarParams radar = radar_for_band(in.radar, {8.6e9, Polarisation::HH});
  EXPECT_DOUBLE_EQ(radar.frequency_hz, 8.6e9);
  SlarOptions keep;
  keep.keep_geometry = true;  // pure_category_map reads the per-sample geometry
  const SlarSimulation sim = simulate_slar(scene, radar, *sigma0, keep);
  const std::vector<std::int32_t> label = pure_category_map(sim);
  ASSERT_EQ(sim.image.lines, 90);
  const auto line_labels = [&](int l) {
    std::set<std::int32_t> s;
    for (int k = 0; k < sim.image.bins; ++k) {
      if (sim.image.mask[sim.image.index(l, k)] == 0) s.insert(label[sim.image.index(l, k)]);
    }
    return s;
  };
  // Block centres: wholly one category.
  EXPECT_EQ(line_labels(45), (std::set<std::int32_t>{2}));
  const auto a = line_labels(15), b = line_labels(74);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(std::set<std::int32_t>({*a.begin(), *b.begin()}), (std::set<std::int32_t>{1, 3}));
  // Next to a boundary the footprint (w = R phi = 25..33 m, 2.5-3.3 lines)
  // mixes categories: nothing attributed.
  // Likewise where it reaches past the track's ends.
  for (int l : {0, 1, 28, 29, 30, 31, 58, 59, 60, 61, 88, 89}) {
    EXPECT_EQ(line_labels(l), (std::set<std::int32_t>{-1})) << l;
  }
}

TEST(Study, BandOutsideTheLibraryNamesBandAndCategory) {
  const Synthetic in;
  const auto sigma0 = load_sigma0_source(in.library);
  const Scene scene = three_blocks();
  const auto bands = parse_study_bands("8.6 GHz:HH, 20 GHz:VV", "--bands");
  const std::string e =
      input_error([&] { run_study(scene, in.radar, *sigma0, in.library, bands); });
  EXPECT_NE(e.find("20 GHz VV"), std::string::npos) << e;
  EXPECT_NE(e.find("grass"), std::string::npos) << e;
  EXPECT_NE(e.find("--bands"), std::string::npos) << e;
}

// The shipped seed case: inputs that exist, the six bands, the middle third.
TEST(Study, SeedFigure7StudyFileIsComplete) {
  const StudyConfig c =
      read_study_config(std::string(test::data_dir()) + "/studies/seed-fig7.toml");
  EXPECT_EQ(c.name, "seed figure 7");
  for (const auto& f : {c.scene, c.radar, c.backscatter}) {
    ASSERT_TRUE(f.has_value());
    EXPECT_TRUE(std::filesystem::exists(*f)) << *f;
  }
  ASSERT_TRUE(c.bands.has_value());
  EXPECT_EQ(parse_study_bands(*c.bands, "bands"), default_study_bands());
  EXPECT_NEAR(*c.range_lo_fraction, 1.0 / 3.0, 1e-9);
  EXPECT_NEAR(*c.range_hi_fraction, 2.0 / 3.0, 1e-9);
  EXPECT_NEAR(*c.incidence_bin_rad, deg_to_rad(1.0), 1e-12);
  const RadarParams radar = load_radar(*c.radar);
  EXPECT_NEAR(radar.track.altitude_m, 4000 * 0.3048, 1e-6);
}

}  // namespace
}  // namespace ris
