#include "ris/sensor/radar_config.h"
#include "build_paths.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "radar_test_util.h"
#include "ris/io/config_table.h"
#include "ris/sensor/elevation_gain.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sensor/radar_json.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

using test::replace;
const auto parse = test::parse_radar;
const auto expect_input_error = test::expect_radar_error;

constexpr double kFt = kFeetToMetres;

std::string radar_file(const std::string& name) {
  return std::string(ris::test::data_dir()) + "/radars/" + name;
}

// A minimal valid radar; tests append or replace lines.
const std::string kMinimal = R"(
mode = "slar"
frequency = "10 GHz"
polarisation = "VV"
pulse_width = "0.1 us"
sweep_delay = "100 us"
sweep_length = "10 us"
azimuth_beamwidth = "1 mrad"
[track]
altitude = "5000 m"
near_edge_distance = "10 km"
)";

// The seed's figure-4-5 radar gives MODEL.md section 2's numbers: R_near ~
// 117,000 ft, 20 deg near-range depression, ~109,900 ft of ground to near
// range, 80 ft range and azimuth resolution, 241 range bins.
TEST(RadarConfig, SeedFigure45DerivedNumbers) {
  const RadarParams r = load_radar(radar_file("seed-fig4-5.toml"));
  EXPECT_EQ(r.mode, RadarMode::slar);
  EXPECT_EQ(r.polarisation, Polarisation::HH);
  EXPECT_NEAR(r.frequency_hz, 8.6e9, 1.0);
  const RadarDerived d = derive(r);
  EXPECT_NEAR(d.near_slant_range_m / kFt, 117000.0, 117000.0 * 0.001);   // 117,045 ft
  EXPECT_NEAR(rad_to_deg(d.near_depression_rad), 20.0, 0.05);            // 19.98 deg
  EXPECT_NEAR(d.near_ground_range_m / kFt, 109900.0, 109900.0 * 0.002);  // 109,998 ft
  EXPECT_NEAR(d.range_resolution_m / kFt, 80.0, 0.5);                    // 80.2 ft
  EXPECT_NEAR(d.range_bin_m, d.range_resolution_m, 1e-9);                // default c tau / 2
  EXPECT_NEAR(d.near_azimuth_footprint_m / kFt, 80.0, 0.5);              // 79.6 ft
  EXPECT_EQ(d.range_bins, 241);                                          // 241.1 -> 241
  // The swath covers the scene's 20,000 ft across track (1000 cells of 20 ft).
  EXPECT_GT(d.far_ground_range_m / kFt, 109900.0 + 20000.0);
  EXPECT_EQ(r.track.kind, TrackSpec::Kind::heading_near_edge);
  EXPECT_NEAR(r.track.near_edge_ground_m / kFt, 109900.0, 1e-6);
  EXPECT_NEAR(r.track.heading_rad, 0.0, 1e-12);
  EXPECT_EQ(r.track.look_side, LookSide::right);
  EXPECT_NEAR(r.track.altitude_m / kFt, 40000.0, 1e-6);
  EXPECT_FALSE(r.independent_samples.has_value());
  // Equation 16: N = 2 R phi^2 / lambda = 0.946 at near range (hand value).
  EXPECT_NEAR(d.near_samples_eq16, 0.9464, 0.001);
  EXPECT_NEAR(d.far_samples_eq16, 2.0 * d.far_slant_range_m * 6.8e-4 * 6.8e-4 / d.wavelength_m,
              1e-9);
  EXPECT_DOUBLE_EQ(d.near_samples, 1.0);  // never fewer than one sample
  EXPECT_EQ(r.fading, FadingLaw::exact_gamma);
  EXPECT_TRUE(r.reference.automatic);
}

TEST(RadarConfig, SeedFigure46DerivedNumbers) {
  const RadarDerived d = derive(load_radar(radar_file("seed-fig4-6.toml")));
  EXPECT_NEAR(rad_to_deg(d.near_depression_rad), 24.0, 0.05);          // 23.995 deg
  EXPECT_NEAR(d.near_ground_range_m / kFt, 89840.0, 89840.0 * 0.002);  // GROUND(1)
  EXPECT_NEAR(d.near_azimuth_footprint_m / kFt, 80.0, 0.5);            // 79.7 ft
  EXPECT_EQ(d.range_bins, 231);                                        // 3.77e-5 / 1.63e-7
  EXPECT_NEAR(d.swath_ground_m / kFt, 20000.0, 100.0);                 // the scene's width
}

TEST(RadarConfig, SeedFigure7LowAltitude) {
  const RadarDerived d = derive(load_radar(radar_file("seed-fig7.toml")));
  EXPECT_NEAR(rad_to_deg(d.near_depression_rad), 40.0, 0.01);
  EXPECT_NEAR(rad_to_deg(d.far_depression_rad), 10.0, 0.01);
  EXPECT_NEAR(d.near_ground_range_m / kFt, 4767.0, 1.0);
  EXPECT_NEAR(d.range_bin_m / kFt, 60.0, 0.01);
  EXPECT_NEAR(d.near_azimuth_footprint_m / kFt, 60.0, 0.1);
  EXPECT_EQ(d.range_bins, 280);  // 16,812 ft / 60 ft = 280.2
}

TEST(RadarConfig, EveryKeyWithUnits) {
  const RadarParams r = parse(R"(
name = "test"
mode = "slar"
frequency = "1.25 GHz"
polarisation = "hv"
pulse_width = 2e-7
near_range = "30 km"
range_bins = 100
range_bin = "20 m"
azimuth_beamwidth = 0.5
transmit_power = "2 kW"
antenna_gain_db = 30
speed = "200 m/s"
prf = "1 kHz"
independent_samples = 4.5
azimuth_line_spacing = "10 m"
[track]
altitude = "6 km"
look_side = "left"
start = ["0 m", "-1 km"]
end = [0, 20000]
[elevation_pattern]
shape = "table"
look_angles = [60, 70, 80]
gain_db = [-3, 0, -3]
[reference]
auto = false
greytone = 100
sigma0_db = -10
area = "1000 ft2"
gain = 10
frequency = "10 GHz"
range = "40 km"
transmit_power = "1 kW"
[film]
density_range = 2.5
gamma = 1.5
k_reference = 1
k_simulated = 2
m_reference = 3
m_simulated = 4
fading = "seed"
[film.terms]
transmit_power = false
wavelength = false
antenna_gain = false
backscatter = false
area = false
range = false
k = false
m = false
fading = false
)");
  EXPECT_EQ(r.name, "test");
  EXPECT_NEAR(r.frequency_hz, 1.25e9, 1e-3);
  EXPECT_EQ(r.polarisation, Polarisation::HV);
  EXPECT_NEAR(r.pulse_width_s, 2e-7, 1e-20);
  EXPECT_NEAR(r.near_slant_range_m, 30000.0, 1e-9);
  EXPECT_EQ(r.range_bins, 100);
  EXPECT_NEAR(r.range_bin_m, 20.0, 1e-12);
  EXPECT_NEAR(r.far_slant_range_m, 32000.0, 1e-9);
  EXPECT_NEAR(r.azimuth_beamwidth_rad, deg_to_rad(0.5), 1e-15);  // bare angle = degrees
  EXPECT_NEAR(r.transmit_power_w, 2000.0, 1e-9);
  EXPECT_NEAR(r.peak_gain, 1000.0, 1e-9);
  EXPECT_NEAR(r.speed_m_per_s, 200.0, 1e-12);
  EXPECT_NEAR(r.prf_hz, 1000.0, 1e-12);
  ASSERT_TRUE(r.independent_samples.has_value());
  EXPECT_DOUBLE_EQ(*r.independent_samples, 4.5);
  EXPECT_NEAR(r.azimuth_line_spacing_m, 10.0, 1e-12);
  EXPECT_EQ(r.track.kind, TrackSpec::Kind::endpoints);
  EXPECT_EQ(r.track.look_side, LookSide::left);
  EXPECT_NEAR(r.track.start_y_m, -1000.0, 1e-9);
  EXPECT_NEAR(r.track.end_y_m, 20000.0, 1e-9);
  EXPECT_EQ(r.elevation_pattern.kind, ElevationPattern::Kind::table);
  ASSERT_EQ(r.elevation_pattern.table_gain.size(), 3u);
  EXPECT_NEAR(r.elevation_pattern.table_gain[0], std::pow(10.0, -0.3), 1e-12);
  EXPECT_FALSE(r.reference.automatic);
  EXPECT_DOUBLE_EQ(r.reference.greytone, 100.0);
  EXPECT_NEAR(r.reference.sigma0, 0.1, 1e-12);
  EXPECT_NEAR(r.reference.area_m2, 1000.0 * kFt * kFt, 1e-9);
  EXPECT_DOUBLE_EQ(r.reference.gain, 10.0);
  EXPECT_NEAR(r.reference.wavelength_m, kSpeedOfLight_m_per_s / 1e10, 1e-12);
  EXPECT_NEAR(r.reference.range_m, 40000.0, 1e-9);
  EXPECT_NEAR(r.reference.transmit_power_w, 1000.0, 1e-9);
  EXPECT_DOUBLE_EQ(r.film.density_range, 2.5);
  EXPECT_DOUBLE_EQ(r.film.gamma, 1.5);
  EXPECT_DOUBLE_EQ(r.film.k2, 2.0);
  EXPECT_DOUBLE_EQ(r.film.m1, 3.0);
  EXPECT_DOUBLE_EQ(r.film.m2, 4.0);
  EXPECT_EQ(r.fading, FadingLaw::seed_eq21);
  const GreytoneSwitches& s = r.switches;
  EXPECT_FALSE(s.transmit_power || s.wavelength || s.antenna_gain || s.backscatter || s.area ||
               s.range || s.film_k || s.receiver_m || s.fading);
}

TEST(RadarConfig, DefaultsFillTheReferenceCellAtMidSwath) {
  const RadarParams r = parse(kMinimal);
  const double c = kSpeedOfLight_m_per_s;
  EXPECT_NEAR(r.range_bin_m, c * 0.1e-6 / 2, 1e-9);
  EXPECT_EQ(r.range_bins, 100);  // 10 us / 0.1 us
  const double mid = 0.5 * (r.near_slant_range_m + r.far_slant_range_m);
  EXPECT_NEAR(r.reference.range_m, mid, 1e-9);
  EXPECT_NEAR(r.reference.wavelength_m, r.wavelength_m(), 1e-15);
  EXPECT_NEAR(r.reference.transmit_power_w, r.transmit_power_w, 1e-12);
  EXPECT_DOUBLE_EQ(r.reference.gain, r.peak_gain);
  const double sin_theta = std::sqrt(1.0 - std::pow(5000.0 / mid, 2));
  EXPECT_NEAR(r.reference.area_m2, mid * 1e-3 * r.range_bin_m / sin_theta, 1e-6);
  EXPECT_TRUE(r.reference.automatic);
  EXPECT_DOUBLE_EQ(r.reference.auto_greytone, 128.0);
  EXPECT_EQ(r.elevation_pattern.kind, ElevationPattern::Kind::uniform);
  EXPECT_NEAR(r.elevation_pattern.boresight_rad, std::acos(5000.0 / mid), 1e-12);
  EXPECT_EQ(r.fading, FadingLaw::exact_gamma);
  EXPECT_TRUE(r.switches.fading && r.switches.area && r.switches.film_k);
  EXPECT_EQ(r.track.look_side, LookSide::right);
}

TEST(RadarConfig, ReferenceByCategoryAndAngle) {
  const RadarParams r = parse(kMinimal + R"(
[reference]
auto = false
greytone = 200
category = 3
incidence = 35
)");
  ASSERT_TRUE(r.reference.sigma0_category.has_value());
  EXPECT_EQ(*r.reference.sigma0_category, 3);
  EXPECT_NEAR(r.reference.sigma0_incidence_rad, deg_to_rad(35.0), 1e-15);
  const RadarParams p = parse(kMinimal + "[reference]\nauto = false\nmean_power = \"2 mW\"\n");
  ASSERT_TRUE(p.reference.mean_power_w.has_value());
  EXPECT_NEAR(*p.reference.mean_power_w, 2e-3, 1e-15);
}

TEST(RadarConfig, BadInputNamesFileAndKey) {
  expect_input_error(kMinimal + "frequncy = \"1 GHz\"\n", "frequncy");  // unknown key
  expect_input_error(replace(kMinimal, "\"slar\"", "\"sar\""), "mode");
  expect_input_error(replace(kMinimal, "\"VV\"", "\"XX\""), "polarisation");
  expect_input_error(replace(kMinimal, "\"0.1 us\"", "0"), "pulse_width");
  expect_input_error(replace(kMinimal, "\"0.1 us\"", "\"-0.1 us\""), "pulse_width");
  expect_input_error(replace(kMinimal, "\"1 mrad\"", "\"-1 mrad\""), "azimuth_beamwidth");
  expect_input_error(replace(kMinimal, "\"1 mrad\"", "0"), "azimuth_beamwidth");
  expect_input_error(replace(kMinimal, "\"10 GHz\"", "\"10 furlongs\""), "frequency");
  // Near range beyond far range.
  expect_input_error(replace(kMinimal, "sweep_length = \"10 us\"", "far_range = \"10 km\""),
                     "far_range");
  expect_input_error(replace(kMinimal, "\"10 us\"", "\"-1 us\""), "sweep_length");
  expect_input_error(replace(kMinimal, "\"10 us\"", "\"0.01 us\""), "sweep_length");  // < 1 bin
  expect_input_error(kMinimal + "near_range = \"1 km\"\n", "near_range");             // both given
  expect_input_error(replace(kMinimal, "sweep_delay = \"100 us\"\n", ""), "sweep_delay");
  expect_input_error(replace(kMinimal, "\"100 us\"", "\"10 us\""), "sweep_delay");  // < altitude
  expect_input_error(replace(kMinimal, "\"5000 m\"", "\"-5 m\""), "altitude");
  expect_input_error(replace(kMinimal, "[track]", "[trac]"), "track");
  expect_input_error(kMinimal + "look_side = \"up\"\n", "look_side");
  expect_input_error(kMinimal + "start = [0, 0]\n", "start");  // both kinds of track
  expect_input_error(
      replace(kMinimal, "near_edge_distance = \"10 km\"", "start = [0, 0]\nend = [\"0 m\", 0]"),
      "end");
  expect_input_error(replace(kMinimal, "[track]", "independent_samples = \"many\"\n[track]"),
                     "independent_samples");
  expect_input_error(replace(kMinimal, "[track]", "independent_samples = 0.5\n[track]"),
                     "independent_samples");
  expect_input_error(replace(kMinimal, "[track]", "range_bins = 10\n[track]"), "range_bins");
  expect_input_error(kMinimal + "[elevation_pattern]\nshape = \"cosine\"\n", "shape");
  expect_input_error(kMinimal + "[elevation_pattern]\nshape = \"sinc2\"\nbeamwidth = -2\n",
                     "beamwidth");
  expect_input_error(
      kMinimal + "[elevation_pattern]\nshape = \"table\"\nlook_angles = [10, 5]\ngain = [1, 1]\n",
      "look_angles");
  expect_input_error(
      kMinimal + "[elevation_pattern]\nshape = \"table\"\nlook_angles = [1, 5]\ngain = [1]\n",
      "gain");
  expect_input_error(kMinimal + "[reference]\nauto = false\n", "sigma0");
  expect_input_error(kMinimal + "[reference]\ngreytone = 300\n", "greytone");
  expect_input_error(kMinimal + "[reference]\nsigma0 = -1\n", "sigma0");
  expect_input_error(kMinimal + "[reference]\nmean_power = 1\n", "mean_power");
  expect_input_error(kMinimal + "[reference]\nincidence = 30\n", "incidence");
  expect_input_error(kMinimal + "[film]\ngamma = 0\n", "gamma");
  expect_input_error(kMinimal + "[film]\ndensity_range = -2\n", "density_range");
  expect_input_error(kMinimal + "[film]\nfading = \"rayleigh\"\n", "fading");
  expect_input_error(kMinimal + "[film.terms]\nbackscater = false\n", "backscater");
}

TEST(RadarConfig, MissingFileIsAnInputError) {
  EXPECT_THROW(load_radar("/nonexistent/radar.toml"), InputError);
}

TEST(ElevationGain, ShapesHaveHalfPowerAtHalfBeamwidth) {
  ElevationPattern p;
  p.beamwidth_rad = deg_to_rad(10.0);
  p.boresight_rad = deg_to_rad(60.0);
  for (auto kind : {ElevationPattern::Kind::sinc2, ElevationPattern::Kind::gaussian}) {
    p.kind = kind;
    const ElevationGain g(p);
    EXPECT_NEAR(g(p.boresight_rad), 1.0, 1e-12);
    EXPECT_NEAR(g(p.boresight_rad + p.beamwidth_rad / 2), 0.5, 1e-7);
    EXPECT_NEAR(g(p.boresight_rad - p.beamwidth_rad / 2), 0.5, 1e-7);
    EXPECT_LT(g(p.boresight_rad + p.beamwidth_rad), 0.1);
  }
  // sinc^2 has its first null at x = 1: beta - b = beamwidth / (2 * 0.442946).
  p.kind = ElevationPattern::Kind::sinc2;
  EXPECT_NEAR(
      ElevationGain(p)(p.boresight_rad + p.beamwidth_rad / (2 * ElevationGain::kSinc2HalfPower)),
      0.0, 1e-12);
  p.kind = ElevationPattern::Kind::uniform;
  EXPECT_DOUBLE_EQ(ElevationGain(p)(0.3), 1.0);
  p.kind = ElevationPattern::Kind::table;
  p.table_look_rad = {0.5, 1.0};
  p.table_gain = {0.2, 0.6};
  const ElevationGain t(p);
  EXPECT_NEAR(t(0.75), 0.4, 1e-12);
  EXPECT_NEAR(t(0.1), 0.2, 1e-12);  // held at the ends
  EXPECT_NEAR(t(1.5), 0.6, 1e-12);
}

}  // namespace
}  // namespace ris

namespace ris {
namespace {

// The complete example in docs/radar-format.md parses and means what it says.
TEST(RadarConfig, DocumentationExampleParses) {
  const std::string doc_path = std::string(ris::test::data_dir()) + "/../docs/radar-format.md";
  std::ifstream f(doc_path);
  ASSERT_TRUE(f) << doc_path;
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string text = ss.str();
  const auto begin = text.find("```toml\n");
  ASSERT_NE(begin, std::string::npos);
  const auto end = text.find("```", begin + 8);
  const RadarParams r =
      radar_from_toml(toml::parse(text.substr(begin + 8, end - begin - 8)), doc_path);
  EXPECT_EQ(r.polarisation, Polarisation::VV);
  EXPECT_EQ(r.range_bins, 400);
  EXPECT_EQ(r.track.look_side, LookSide::left);
  EXPECT_EQ(r.elevation_pattern.kind, ElevationPattern::Kind::gaussian);
  EXPECT_EQ(r.fading, FadingLaw::seed_eq21);
  EXPECT_FALSE(r.switches.range);
  EXPECT_TRUE(r.switches.area);
  ASSERT_TRUE(r.reference.sigma0_category.has_value());
  EXPECT_EQ(*r.reference.sigma0_category, 3);
}

}  // namespace
}  // namespace ris

namespace ris {
namespace {

TEST(RadarJson, RecordsInputsDerivedAndSwitches) {
  const RadarParams r = load_radar(radar_file("seed-fig4-5.toml"));
  const nlohmann::json j = radar_to_json(r);
  EXPECT_EQ(j["polarisation"], "HH");
  EXPECT_EQ(j["range_bins"], 241);
  EXPECT_NEAR(j["track"]["near_edge_distance_m"].get<double>(), 109900 * kFeetToMetres, 1e-6);
  EXPECT_EQ(j["film"]["fading"], "exact");
  EXPECT_EQ(j["film"]["terms"]["backscatter"], true);
  EXPECT_EQ(j["independent_samples"], "seed equation 16");
  const nlohmann::json d = derived_to_json(derive(r));
  EXPECT_NEAR(d["near_depression_rad"].get<double>(), deg_to_rad(19.983), 1e-4);
  EXPECT_EQ(d["range_bins"], 241);
  EXPECT_NO_THROW((void)j.dump());
}

}  // namespace
}  // namespace ris

namespace ris {
namespace {

// radar_at_band gives what the file gives with `frequency` and
// `polarisation` replaced (the study used to rewrite the TOML that way): for
// every shipped radar, and for a reference with its own wavelength, at two
// bands. Exact: the same arithmetic on the same inputs.
TEST(RadarAtBand, SameAsTheFileWithFrequencyAndPolarisationReplaced) {
  std::vector<std::pair<std::string, toml::table>> docs;
  for (const char* name :
       {"seed-fig4-5.toml", "seed-fig4-6.toml", "seed-fig7.toml", "sar-x-band-stripmap.toml",
        "ppi-ground-mast-30m.toml", "ppi-airborne-nav-10000ft.toml"}) {
    docs.emplace_back(radar_file(name), parse_toml_file(radar_file(name)));
  }
  toml::table own_wavelength = toml::parse(kMinimal);
  own_wavelength.insert_or_assign("reference", toml::table{{"wavelength", "0.05 m"}});
  docs.emplace_back("own-wavelength.toml", own_wavelength);
  for (const auto& [file, doc] : docs) {
    const RadarParams base = radar_from_toml(doc, file);
    for (const auto& [f_hz, pol] :
         {std::pair{1.25e9, Polarisation::HV}, std::pair{13e9, Polarisation::VV}}) {
      toml::table rewritten = doc;
      rewritten.insert_or_assign("frequency", fmt::format("{:.12g} Hz", f_hz));
      rewritten.insert_or_assign("polarisation", std::string(to_string(pol)));
      const RadarParams want = radar_from_toml(rewritten, file);
      const RadarParams got = radar_at_band(base, f_hz, pol);
      EXPECT_EQ(got.frequency_hz, want.frequency_hz) << file;
      EXPECT_EQ(got.polarisation, want.polarisation) << file;
      EXPECT_EQ(got.reference.wavelength_m, want.reference.wavelength_m) << file;
      EXPECT_EQ(got.azimuth_beamwidth_rad, want.azimuth_beamwidth_rad) << file;
      EXPECT_EQ(radar_to_json(got).dump(), radar_to_json(want).dump()) << file;
      EXPECT_EQ(derived_to_json(derive(got)).dump(), derived_to_json(derive(want)).dump()) << file;
    }
  }
  // The reference's own wavelength stays; a SAR's lambda / L follows.
  const RadarParams own = radar_from_toml(own_wavelength, "own.toml");
  EXPECT_DOUBLE_EQ(radar_at_band(own, 1e9, Polarisation::HH).reference.wavelength_m, 0.05);
  const RadarParams sar = load_radar(radar_file("sar-x-band-stripmap.toml"));
  EXPECT_NEAR(radar_at_band(sar, 1e9, Polarisation::HH).azimuth_beamwidth_rad,
              kSpeedOfLight_m_per_s / 1e9 / (2.0 * 7.5), 1e-15);
}

TEST(RadarAtBand, BeamwidthPast180DegreesNamesFileAndKey) {
  RadarParams sar = load_radar(radar_file("sar-x-band-stripmap.toml"));
  sar.beamwidth_antenna_length_m = 0.05;  // lambda / L > pi at 1 GHz (0.3 m / 0.05 m)
  try {
    radar_at_band(sar, 1e9, Polarisation::HH);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "azimuth_beamwidth");
    EXPECT_NE(std::string(e.what()).find("sar-x-band-stripmap.toml"), std::string::npos);
  }
}

}  // namespace
}  // namespace ris

namespace ris {
namespace {

// `earth = "flat" | "ellipsoid"` (docs/radar-format.md): absent by default
// (the run chooses), anything else refused naming the key.
TEST(RadarConfig, EarthModelKey) {
  EXPECT_FALSE(test::parse_radar(kMinimal).earth.has_value());
  EXPECT_EQ(test::parse_radar("earth = \"flat\"\n" + kMinimal).earth, EarthModel::flat);
  EXPECT_EQ(test::parse_radar("earth = \"ellipsoid\"\n" + kMinimal).earth, EarthModel::ellipsoid);
  test::expect_radar_error("earth = \"round\"\n" + kMinimal, "earth");
}

}  // namespace
}  // namespace ris
