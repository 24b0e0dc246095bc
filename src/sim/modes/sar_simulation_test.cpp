// SAR stripmap, incoherent (the box resolution cell): flat-plane radiometry
// with the multilooked cell, constant azimuth resolution against SLAR's
// R phi, NESZ noise in shadows, the resolution warning (MODEL.md section 3).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ris/image/greytone_terms.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

constexpr double kCell = 2.0;
constexpr double kH = 1000.0;

// 100 rows (200 m along track) x 500 columns (1000 m across), west edge 1000 m
// from a north-bound, east-looking track at 1000 m.
Scene strip_scene() {
  return Scene::flat(100, 500, kCell, 0.0f, 0);
}

std::string common(const std::string& mode) {
  return "mode = \"" + mode + R"("
frequency = "9.6 GHz"
polarisation = "VV"
near_range = "1400 m"
far_range = "2250 m"
transmit_power = "1 kW"
antenna_gain_db = 30
[track]
altitude = "1000 m"
near_edge_distance = "1000 m"
)";
}

RadarParams sar_radar(const std::string& sar_keys) {
  return radar_from_toml(toml::parse(common("sar") + "[sar]\n" + sar_keys), "sar.toml");
}

RadarParams slar_radar() {
  return radar_from_toml(
      toml::parse("pulse_width = \"20 ns\"\nazimuth_beamwidth = \"10 mrad\"\n" + common("slar")),
      "slar.toml");
}

PointTarget target(double x, double y, double rcs) {
  PointTarget t;
  t.name = "t";
  t.x_m = x;
  t.y_m = y;
  t.rcs_m2 = rcs;
  return t;
}

// The azimuth equivalent width (sum over lines / peak x line spacing) of the
// power a target adds in its brightest range bin.
double equivalent_azimuth_width_m(const SlarImage& with, const SlarImage& without) {
  std::size_t best = 0;
  for (std::size_t i = 0; i < with.mean_power_w.size(); ++i)
    if (with.mean_power_w[i] - without.mean_power_w[i] >
        with.mean_power_w[best] - without.mean_power_w[best])
      best = i;
  const int bin = static_cast<int>(best % static_cast<std::size_t>(with.bins));
  double sum = 0.0, peak = 0.0;
  for (int line = 0; line < with.lines; ++line) {
    const double d = double(with.mean_power_w[with.index(line, bin)]) -
                     without.mean_power_w[without.index(line, bin)];
    sum += d;
    peak = std::max(peak, d);
  }
  return sum / peak * with.line_spacing_m;
}

TEST(SarSimulation, FlatPlanePixelHoldsTheMultilookedResolutionCell) {
  const Scene s = strip_scene();
  const RadarParams r =
      sar_radar("range_resolution = \"3 m\"\nazimuth_resolution = \"4 m\"\nrange_looks = 2\n");
  ASSERT_DOUBLE_EQ(r.range_bin_m, 3.0);
  const SlarSimulation sim = simulate_slar(s, r, test::CosineSigma0Source());
  const SlarImage& img = sim.image;
  const double k =
      radar_equation_power_w(r.transmit_power_w, 1.0, 1.0, r.peak_gain, r.wavelength_m(), 1.0);
  double worst = 0.0;
  for (int b = 20; b < img.bins - 20; b += 7) {
    const double R = img.range.centre_m(b);
    const double theta = std::acos(kH / R);
    // sigma0(theta) (L_a rho_a) (L_r rho_r) / sin(theta) / R^4: 4 m x 6 m.
    const double expected = k * test::CosineSigma0Source::gamma(0) * std::cos(theta) * 4.0 * 6.0 /
                            std::sin(theta) / std::pow(R, 4);
    worst = std::max(worst, std::abs(img.mean_power_w[img.index(50, b)] / expected - 1.0));
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  // Measured 1.3e-4 (range and angle across a bin against its centre's).
  EXPECT_LT(worst, 5e-4);
}

TEST(SarSimulation, AzimuthResolutionIsConstantWhileSlarGrowsWithRange) {
  const Scene s = strip_scene();
  const auto widths = [&](const RadarParams& r, double x) {
    SlarOptions opt;
    opt.targets = {target(x, 100.0, 1e5)};
    const SlarSimulation with = simulate_slar(s, r, test::CosineSigma0Source(), opt);
    const SlarSimulation without = simulate_slar(s, r, test::CosineSigma0Source());
    return equivalent_azimuth_width_m(with.image, without.image);
  };
  // Near (u = 1200 m) and far (u = 1900 m) targets.
  const RadarParams sar = sar_radar("range_resolution = \"3 m\"\nantenna_length = \"16 m\"\n");
  EXPECT_NEAR(widths(sar, 200.0), 8.0, 0.08);  // L / 2
  EXPECT_NEAR(widths(sar, 900.0), 8.0, 0.08);
  const RadarParams slar = slar_radar();
  const double r_near = std::hypot(1200.0, kH), r_far = std::hypot(1900.0, kH);
  const double w_near = widths(slar, 200.0), w_far = widths(slar, 900.0);
  EXPECT_NEAR(w_near / (r_near * 0.01), 1.0, 0.05);  // R phi
  EXPECT_NEAR(w_far / (r_far * 0.01), 1.0, 0.05);
  EXPECT_NEAR((w_far / w_near) / (r_far / r_near), 1.0, 0.05);  // grows as R
}

TEST(SarSimulation, NeszPutsNoiseIntoShadowsAndEveryPixel) {
  Scene s = strip_scene();
  for (int r = 30; r < 70; ++r)
    for (int c = 100; c < 110; ++c) s.elevation_m[s.index(r, c)] = 300.0f;  // casts shadow
  const std::string keys = "range_resolution = \"3 m\"\nazimuth_resolution = \"4 m\"\n";
  const SlarSimulation quiet = simulate_slar(s, sar_radar(keys), test::CosineSigma0Source());
  const SlarSimulation noisy =
      simulate_slar(s, sar_radar(keys + "nesz_db = -20\n"), test::CosineSigma0Source());
  ASSERT_EQ(noisy.noise_power_w.size(), static_cast<std::size_t>(noisy.image.bins));
  const RadarParams r = noisy.radar;
  int shadow = 0;
  for (int line = 0; line < noisy.image.lines; ++line) {
    for (int b = 0; b < noisy.image.bins; ++b) {
      const std::size_t i = noisy.image.index(line, b);
      const double pn = noisy.noise_power_w[static_cast<std::size_t>(b)];
      ASSERT_NEAR(noisy.image.mean_power_w[i] - quiet.image.mean_power_w[i], pn, 1e-5 * pn);
      if (noisy.image.mask[i] & pixel_flag::kShadow) {
        ++shadow;
        EXPECT_EQ(quiet.image.mean_power_w[i], 0.0f);
        EXPECT_GT(noisy.image.mean_power_w[i], 0.0f);
      }
    }
  }
  EXPECT_GT(shadow, 100);
  // The noise is flat ground of sigma0 = NESZ: P_n(R) = k G^2 NESZ A / R^4.
  const int b = 100;
  const double R = noisy.image.range.centre_m(b);
  const double sin_t = std::sqrt(1.0 - std::pow(kH / R, 2));
  EXPECT_NEAR(
      noisy.noise_power_w[b] / radar_equation_power_w(r.transmit_power_w, 0.01, 4.0 * 3.0 / sin_t,
                                                      r.peak_gain, r.wavelength_m(), R),
      1.0, 1e-9);
}

TEST(SarSimulation, ResolutionFinerThanTheSceneWarnsWithTheConsequence) {
  const Scene s = strip_scene();
  const SlarSimulation fine =
      simulate_slar(s, sar_radar("bandwidth = \"600 MHz\"\nantenna_length = \"2 m\"\n"),
                    test::CosineSigma0Source());
  ASSERT_EQ(fine.warnings.size(), 2u);
  EXPECT_NE(fine.warnings[0].find("azimuth resolution (1.00 m, half the 2.00 m antenna)"),
            std::string::npos)
      << fine.warnings[0];
  EXPECT_NE(fine.warnings[1].find("B = 600.0 MHz"), std::string::npos) << fine.warnings[1];
  EXPECT_NE(fine.warnings[1].find("no detail finer than the scene's cells"), std::string::npos);
  const SlarSimulation ok =
      simulate_slar(s, sar_radar("bandwidth = \"30 MHz\"\nantenna_length = \"8 m\"\n"),
                    test::CosineSigma0Source());
  EXPECT_TRUE(ok.warnings.empty());
}

}  // namespace
}  // namespace ris
