// Radar files for the SAR and PPI modes: keys, defaults, derived values and
// bad input (docs/radar-format.md, "SAR" and "PPI").
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "radar_test_util.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sensor/radar_json.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

using test::replace;
const auto parse = test::parse_radar;
const auto expect_input_error = test::expect_radar_error;

const std::string kSar = R"(
mode = "sar"
frequency = "9.6 GHz"
polarisation = "VV"
near_range = "5000 m"
far_range = "6000 m"
range_bin = "1 m"
[sar]
bandwidth = "100 MHz"
antenna_length = "3 m"
range_looks = 2
azimuth_looks = 3
nesz_db = -25
[track]
altitude = "3000 m"
near_edge_distance = "4000 m"
)";

const std::string kPpi = R"(
mode = "ppi"
frequency = "9.41 GHz"
polarisation = "HH"
pulse_width = "0.1 us"
near_range = 0
far_range = "3 km"
azimuth_beamwidth = "1.2 deg"
[site]
position = [500.0, 600.0]
height = "30 m"
[scan]
start = "10 deg"
width = "90 deg"
range_rings = "1 km"
)";

TEST(RadarModes, SarResolutionsFromBandwidthAndAntennaLength) {
  const RadarParams r = parse(kSar);
  EXPECT_EQ(r.mode, RadarMode::sar);
  EXPECT_NEAR(r.sar.range_resolution_m, kSpeedOfLight_m_per_s / 2e8, 1e-9);  // 1.499 m
  EXPECT_DOUBLE_EQ(r.sar.azimuth_resolution_m, 1.5);                         // L / 2
  EXPECT_DOUBLE_EQ(r.range_bin_m, 1.0);  // sampling set separately
  EXPECT_EQ(r.range_bins, 1000);
  EXPECT_DOUBLE_EQ(*r.independent_samples, 6.0);  // L_r L_a
  EXPECT_NEAR(*r.sar.nesz, std::pow(10.0, -2.5), 1e-12);
  EXPECT_FALSE(r.sar.coherent);
  // The real beamwidth lambda / L.
  EXPECT_NEAR(r.azimuth_beamwidth_rad, r.wavelength_m() / 3.0, 1e-12);
  const RadarDerived d = derive(r);
  EXPECT_NEAR(d.range_resolution_m, 1.499, 1e-3);
  EXPECT_DOUBLE_EQ(d.near_azimuth_footprint_m, 4.5);  // L_a rho_a, same at far range
  EXPECT_DOUBLE_EQ(d.far_azimuth_footprint_m, 4.5);
  EXPECT_EQ(radar_to_json(r)["sar"]["azimuth_looks"], 3);
}

TEST(RadarModes, SarDefaultRangeBinIsTheResolutionAndResolutionMayBeGiven) {
  std::string t = kSar;
  t = replace(t, "range_bin = \"1 m\"\n", "");
  t = replace(t, "bandwidth = \"100 MHz\"", "range_resolution = \"2.5 m\"");
  t = replace(t, "antenna_length = \"3 m\"", "azimuth_resolution = \"2 m\"");
  const RadarParams r = parse(t);
  EXPECT_DOUBLE_EQ(r.range_bin_m, 2.5);
  EXPECT_DOUBLE_EQ(r.sar.azimuth_resolution_m, 2.0);
  EXPECT_NEAR(r.azimuth_beamwidth_rad, r.wavelength_m() / 4.0, 1e-12);
}

TEST(RadarModes, SarBadInput) {
  expect_input_error(replace(kSar, "[sar]", "[sarr]"), "sar");
  std::string t = kSar;
  t = replace(t, "antenna_length = \"3 m\"", "antena_length = \"3 m\"");
  expect_input_error(t, "antenna_length");
  t = kSar;
  t = replace(t, "range_looks = 2", "range_looks = 0");
  expect_input_error(t, "range_looks");
  t = kSar;
  t = replace(t, "nesz_db = -25", "nesz_db = -25\nnesz = 0.01");
  expect_input_error(t, "nesz");
  // A [sar] table in another mode.
  t = kSar;
  t = replace(t, "mode = \"sar\"",
              "mode = \"slar\"\npulse_width = \"0.1 us\"\n"
              "azimuth_beamwidth = \"1 deg\"");
  expect_input_error(t, "sar");
}

TEST(RadarModes, PpiSiteScanAndDefaults) {
  const RadarParams r = parse(kPpi);
  EXPECT_EQ(r.mode, RadarMode::ppi);
  EXPECT_DOUBLE_EQ(r.ppi.site_x_m, 500.0);
  EXPECT_DOUBLE_EQ(r.ppi.site_y_m, 600.0);
  EXPECT_DOUBLE_EQ(*r.ppi.height_above_ground_m, 30.0);
  EXPECT_FALSE(r.ppi.altitude_m.has_value());
  EXPECT_DOUBLE_EQ(r.near_slant_range_m, 0.0);
  EXPECT_NEAR(r.ppi.scan_start_rad, deg_to_rad(10.0), 1e-12);
  EXPECT_NEAR(r.ppi.scan_width_rad, deg_to_rad(90.0), 1e-12);
  // Rays at most half a beamwidth apart, whole rays over the sector: 150.
  EXPECT_NEAR(r.ppi.ray_spacing_rad, deg_to_rad(0.6), 1e-12);
  EXPECT_DOUBLE_EQ(r.ppi.ring_spacing_m, 1000.0);
  EXPECT_DOUBLE_EQ(r.ppi.scope_pixel_m, r.range_bin_m);
  EXPECT_EQ(r.ppi.presentation, PpiPresentation::slant);
  EXPECT_FALSE(r.ppi.full_circle());
  EXPECT_EQ(radar_to_json(r)["mode"], "ppi");
  // Without [scan]: all round.
  std::string t = kPpi.substr(0, kPpi.find("[scan]"));
  EXPECT_TRUE(parse(t).ppi.full_circle());
}

TEST(RadarModes, PpiBadInput) {
  std::string t = kPpi;
  t = replace(t, "width = \"90 deg\"", "width = 0");
  expect_input_error(t, "scan.width");
  t = kPpi;
  t = replace(t, "width = \"90 deg\"", "width = \"90 deg\"\nray_spacing = \"1 deg\"");
  expect_input_error(t, "scan.ray_spacing");  // more than half the 1.2 deg beam
  t = kPpi;
  t = replace(t, "height = \"30 m\"", "height = \"30 m\"\naltitude = \"100 m\"");
  expect_input_error(t, "site");
  t = kPpi;
  t = replace(t, "position = [500.0, 600.0]", "position = [500.0]");
  expect_input_error(t, "site.position");
  t = kPpi;
  t = replace(t, "range_rings", "range_ring");
  expect_input_error(t, "range_ring");
  // A PPI has no track; a SLAR no site.
  expect_input_error(kPpi + "[track]\naltitude = 100\n", "track");
}

}  // namespace
}  // namespace ris
