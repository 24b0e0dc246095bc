// Every switch of the seed's equation 15 (MODEL.md section 3, "Greytone";
// ris/image/greytone_terms.h) checked on the simulated image itself: a flat
// scene simulated with all terms on and with one term off, and each pixel's
// mean power (or greytone, for k and M) compared with the term's analytic
// ratio. The reference cell differs from the radar in every factor, so a
// switch that is ignored, or replaces the wrong value, moves the ratio.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ris/sensor/elevation_gain.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

// 9.6 GHz, 15 m bins over 4300-5500 m of slant range from 3000 m up, a
// Gaussian elevation beam; the reference cell: 2 kW, 25 dB, 5 GHz,
// sigma0 0.3, 500 m^2 at 4000 m.
RadarParams switch_radar(const std::string& term_off) {
  std::string doc = R"(
mode = "slar"
frequency = "9.6 GHz"
polarisation = "HH"
pulse_width = "0.1 us"
near_range = "4300 m"
far_range = "5500 m"
azimuth_beamwidth = "0.2 deg"
transmit_power = "10 kW"
antenna_gain_db = 30
[elevation_pattern]
shape = "gaussian"
beamwidth = "30 deg"
boresight = "50 deg"
[reference]
auto = false
greytone = 100
transmit_power = "2 kW"
gain_db = 25
frequency = "5 GHz"
sigma0 = 0.3
area = 500
range = "4000 m"
[film]
density_range = 2.5
gamma = 0.8
k_reference = 1.0
k_simulated = 3.0
m_reference = 1.0
m_simulated = 0.5
[film.terms]
fading = false
)";
  if (!term_off.empty()) doc += term_off + " = false\n";
  doc += R"(
[track]
altitude = "3000 m"
heading = "0 deg"
near_edge_distance = "3000 m"
)";
  return radar_from_toml(toml::parse(doc), "switches.toml");
}

constexpr double kH = 3000.0;

struct Pair {
  SlarSimulation on, off;
};

Pair simulate_pair(const std::string& term) {
  // 3 km x 2 km of flat ground, 10 m cells, from 3 km east of the track.
  const Scene s = Scene::flat(200, 300, 10.0, 0.0f, 0);
  const test::CosineSigma0Source sigma0;
  return {simulate_slar(s, switch_radar(""), sigma0), simulate_slar(s, switch_radar(term), sigma0)};
}

// Calls check(line, bin, off / on) for the pixels well inside the scene.
template <typename Check>
int for_inner_pixels(const Pair& p, Check check) {
  const SlarImage& a = p.on.image;
  int n = 0;
  for (int line = 20; line < a.lines - 20; line += 9) {
    for (int b = 2; b < a.bins - 2; ++b) {
      const std::size_t i = a.index(line, b);
      if (a.mask[i] != 0 || !(a.mean_power_w[i] > 0.0f)) continue;
      check(line, b, double(p.off.image.mean_power_w[i]) / double(a.mean_power_w[i]));
      ++n;
    }
  }
  return n;
}

TEST(Equation15Switches, TransmitPowerOffFormsTheImageWithTheReferencePower) {
  const Pair p = simulate_pair("transmit_power");
  const int n = for_inner_pixels(p, [](int, int, double ratio) {
    EXPECT_NEAR(ratio, 2e3 / 1e4, 1e-6 * 0.2);  // float pixels (2^-24 = 6e-8 each)
  });
  EXPECT_GT(n, 1000);
}

TEST(Equation15Switches, WavelengthOffFormsTheImageWithTheReferenceWavelength) {
  const Pair p = simulate_pair("wavelength");
  const double want = std::pow(9.6 / 5.0, 2);  // (lambda_1 / lambda)^2 = (f / f_1)^2
  const int n =
      for_inner_pixels(p, [&](int, int, double ratio) { EXPECT_NEAR(ratio, want, 1e-6 * want); });
  EXPECT_GT(n, 1000);
}

TEST(Equation15Switches, AntennaGainOffSeesEveryElementWithTheReferenceGain) {
  const Pair p = simulate_pair("antenna_gain");
  const RadarParams r = switch_radar("");
  const ElevationGain ge(r.elevation_pattern);
  const double g1 = std::pow(10.0, 2.5), g0 = std::pow(10.0, 3.0);
  double worst = 0.0;
  const int n = for_inner_pixels(p, [&](int, int b, double ratio) {
    // Off: G_1^2 for every element; on: (G_0 G_e(beta))^2, beta the bin
    // centre's look angle on flat ground (cos beta = H / R).
    const double beta = std::acos(kH / p.on.image.range.centre_m(b));
    const double want = (g1 * g1) / std::pow(g0 * ge(beta), 2);
    worst = std::max(worst, std::abs(ratio / want - 1.0));
  });
  EXPECT_GT(n, 1000);
  // Measured 1.6e-4: G_e varies across a 15 m bin (the elements' look angles
  // against the bin centre's).
  EXPECT_LT(worst, 5e-4);
}

TEST(Equation15Switches, BackscatterOffGivesEveryElementTheReferenceSigma0) {
  const Pair p = simulate_pair("backscatter");
  double worst = 0.0;
  const double gamma = test::CosineSigma0Source::gamma(0);
  const int n = for_inner_pixels(p, [&](int, int b, double ratio) {
    // On flat ground the local incidence is the look angle: sigma0 = gamma H / R.
    const double sigma0 = gamma * kH / p.on.image.range.centre_m(b);
    const double want = 0.3 / sigma0;
    worst = std::max(worst, std::abs(ratio / want - 1.0));
  });
  EXPECT_GT(n, 1000);
  // Measured 5.9e-5: cos(theta) across a bin against its centre's.
  EXPECT_LT(worst, 2e-4);
}

TEST(Equation15Switches, RangeOffTakesEveryPixelToTheReferenceRange) {
  const Pair p = simulate_pair("range");
  const int n = for_inner_pixels(p, [&](int, int b, double ratio) {
    const double q = p.on.image.range.centre_m(b) / 4000.0;
    EXPECT_NEAR(ratio, q * q * q * q, 1e-6 * q * q * q * q);
  });
  EXPECT_GT(n, 1000);
}

TEST(Equation15Switches, AreaOffGivesEveryPixelTheReferenceArea) {
  const Pair p = simulate_pair("area");
  double worst = 0.0;
  const double phi = 0.2 * kPi / 180.0;
  const int n = for_inner_pixels(p, [&](int, int b, double ratio) {
    // A flat pixel's summed true area: the footprint R phi times the bin's
    // ground width dr / sin(theta) (MODEL.md section 3, "Image formation").
    const double R = p.on.image.range.centre_m(b);
    const double sin_theta = std::sqrt(1.0 - (kH / R) * (kH / R));
    const double area = R * phi * p.on.image.range.bin_m / sin_theta;
    worst = std::max(worst, std::abs(ratio / (500.0 / area) - 1.0));
  });
  EXPECT_GT(n, 1000);
  // Measured 3.6e-5: the cells summed over the footprint and the bin
  // against the exact flat-ground area.
  EXPECT_LT(worst, 1e-4);
}

// k and M act in the greytone map: off, the greytone loses (255/X)
// log10(k2/k1), respectively (255/X) gamma log10(M2/M1).
TEST(Equation15Switches, KAndMOffRemoveTheirGreytoneTerms) {
  const Scene s = Scene::flat(200, 300, 10.0, 0.0f, 0);
  const test::CosineSigma0Source sigma0;
  const SlarSimulation sim = simulate_slar(s, switch_radar(""), sigma0);
  const SlarPictures on = render_slar(sim, 1);
  for (const auto& [term, shift] :
       {std::pair<std::string, double>{"k", 255.0 / 2.5 * std::log10(3.0)},
        std::pair<std::string, double>{"m", 255.0 / 2.5 * 0.8 * std::log10(0.5)}}) {
    SlarSimulation off_sim = sim;
    off_sim.radar = switch_radar(term);
    const SlarPictures off = render_slar(off_sim, 1);
    EXPECT_NEAR(on.film_offset - off.film_offset, shift, 1e-9) << term;
    double mean_diff = 0.0;
    int n = 0;
    for (std::size_t i = 0; i < on.slant_grey.size(); ++i) {
      if (on.slant_grey[i] == 0 || on.slant_grey[i] == 255) continue;  // clamped
      if (off.slant_grey[i] == 0 || off.slant_grey[i] == 255) continue;
      mean_diff += double(on.slant_grey[i]) - double(off.slant_grey[i]);
      ++n;
    }
    ASSERT_GT(n, 1000) << term;
    // Each greytone is rounded: the mean difference is the shift within 0.5.
    EXPECT_NEAR(mean_diff / n, shift, 0.5) << term;
  }
}

}  // namespace
}  // namespace ris
