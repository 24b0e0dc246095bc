#include "ris/image/greytone.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "ris/image/greytone_image.h"
#include "ris/image/greytone_terms.h"
#include "ris/image/speckle.h"
#include "ris/sensor/elevation_gain.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/radar_derived.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

// A radar with an explicit reference cell whose every factor differs from
// the simulated radar's, and film constants k2 != k1, M2 != M1.
const std::string kRadar = R"(
mode = "slar"
frequency = "9.6 GHz"
polarisation = "HH"
pulse_width = "0.1 us"
sweep_delay = "100 us"
sweep_length = "10 us"
azimuth_beamwidth = "1 mrad"
transmit_power = "20 kW"
antenna_gain_db = 30
[track]
altitude = "5000 m"
near_edge_distance = "10 km"
[elevation_pattern]
shape = "gaussian"
beamwidth = "20 deg"
boresight = "70 deg"
[reference]
auto = false
greytone = 90
transmit_power = "5 kW"
sigma0_db = -12
area = 600
gain_db = 27
frequency = "8.6 GHz"
range = "14 km"
[film]
density_range = 2.5
gamma = 0.8
k_reference = 1.0
k_simulated = 2.0
m_reference = 1.0
m_simulated = 0.5
)";

RadarParams radar_with(const std::string& extra = "") {
  return radar_from_toml(toml::parse(kRadar + extra), "r.toml");
}

constexpr double kTol = 1e-9;  // greytones, real-valued

TEST(Greytone, ReferencePowerGivesReferenceGreytone) {
  const RadarParams r = radar_with("[film.terms]\nk = false\nm = false\n");
  const GreytoneMap map = make_greytone_map(r, {});
  const double p_ref = reference_power_w(r.reference);
  EXPECT_NEAR(map.reference_power_w(), p_ref, 1e-12 * p_ref);
  EXPECT_NEAR(map.greytone(p_ref), 90.0, kTol);
  EXPECT_EQ(map.quantised(p_ref), 90);
  // Equation 3 by hand: P_T1 sigma0 dA G^2 lambda^2 / ((4 pi)^3 R^4).
  const double lambda1 = kSpeedOfLight_m_per_s / 8.6e9;
  const double by_hand = 5000.0 * std::pow(10.0, -1.2) * 600.0 * std::pow(10.0, 5.4) * lambda1 *
                         lambda1 / (std::pow(4 * kPi, 3) * std::pow(14000.0, 4));
  EXPECT_NEAR(p_ref, by_hand, 1e-12 * by_hand);
}

TEST(Greytone, FactorTenInPowerMovesGBy255GammaOverX) {
  const GreytoneMap map = make_greytone_map(radar_with(), {});
  const double step = 255.0 * 0.8 / 2.5;
  EXPECT_NEAR(map.greytones_per_decade(), step, kTol);
  for (double p : {1e-15, 3e-12, 7e-9}) {
    EXPECT_NEAR(map.greytone(10 * p) - map.greytone(p), step, kTol);
    EXPECT_NEAR(map.greytone(p / 100) - map.greytone(p), -2 * step, kTol);
  }
}

// The k and M terms: on, they shift every greytone by (255/X) log10(k2/k1)
// and (255/X) gamma log10(M2/M1); off, their ratio is one.
TEST(Greytone, FilmSwitchesKAndM) {
  const double scale = 255.0 / 2.5;
  const double k_term = scale * std::log10(2.0);
  const double m_term = scale * 0.8 * std::log10(0.5);
  struct Case {
    std::string terms;
    double shift;
  };
  for (const Case& c : {Case{"", k_term + m_term}, Case{"k = false\n", m_term},
                        Case{"m = false\n", k_term}, Case{"k = false\nm = false\n", 0.0}}) {
    const RadarParams r = radar_with("[film.terms]\n" + c.terms);
    const GreytoneMap map = make_greytone_map(r, {});
    EXPECT_NEAR(map.greytone(map.reference_power_w()) - 90.0, c.shift, kTol) << c.terms;
  }
}

// A pixel that differs from the reference cell in every factor. For each
// radar-equation term switched off, the pixel's greytone differs from G_ref
// by exactly the remaining terms: the switched-off term's ratio is one.
TEST(Greytone, EachRadarEquationSwitchGivesTheReferenceRatio) {
  struct Pixel {
    double sigma0 = 0.02, area_m2 = 900.0, look_rad = deg_to_rad(63.0), range_m = 16000.0;
  } px;
  const std::vector<std::string> terms = {"transmit_power", "wavelength", "antenna_gain",
                                          "backscatter",    "area",       "range"};
  // The pixel's power with the switches of `r`, as the simulation forms it.
  auto pixel_power = [&](const RadarParams& r) {
    const SwitchedRadarTerms t = switched_terms(r);
    const double ge = t.uniform_elevation ? 1.0 : ElevationGain(r.elevation_pattern)(px.look_rad);
    const double sigma0 = t.constant_sigma0.value_or(px.sigma0);
    return radar_equation_power_w(t.transmit_power_w, sigma0, px.area_m2, t.peak_gain * ge,
                                  t.wavelength_m, px.range_m) *
           range_correction(t, px.range_m) * area_correction(t, px.area_m2);
  };
  const RadarParams all_on = radar_with("[film.terms]\nk = false\nm = false\n");
  const ReferenceCell& ref = all_on.reference;
  const double ge = ElevationGain(all_on.elevation_pattern)(px.look_rad);
  // log10 of each term's ratio (simulated / reference), equation 15.
  const std::vector<double> log_ratio = {std::log10(all_on.transmit_power_w / ref.transmit_power_w),
                                         2 * std::log10(all_on.wavelength_m() / ref.wavelength_m),
                                         2 * std::log10(all_on.peak_gain * ge / ref.gain),
                                         std::log10(px.sigma0 / ref.sigma0),
                                         std::log10(px.area_m2 / ref.area_m2),
                                         4 * std::log10(ref.range_m / px.range_m)};
  double total = 0.0;
  for (double l : log_ratio) {
    EXPECT_GT(std::abs(l), 0.01);  // every term really differs
    total += l;
  }
  const double per_decade = 255.0 * 0.8 / 2.5;
  const GreytoneMap on_map = make_greytone_map(all_on, {});
  EXPECT_NEAR(on_map.greytone(pixel_power(all_on)), 90.0 + per_decade * total, 1e-7);
  for (size_t i = 0; i < terms.size(); ++i) {
    const RadarParams r =
        radar_with("[film.terms]\nk = false\nm = false\n" + terms[i] + " = false\n");
    const GreytoneMap map = make_greytone_map(r, {});
    EXPECT_NEAR(map.greytone(pixel_power(r)), 90.0 + per_decade * (total - log_ratio[i]), 1e-7)
        << terms[i] << " off";
  }
  // All six off: the pixel is the reference cell.
  std::string off = "[film.terms]\nk = false\nm = false\n";
  for (const auto& t : terms) off += t + " = false\n";
  const RadarParams r = radar_with(off);
  EXPECT_NEAR(make_greytone_map(r, {}).greytone(pixel_power(r)), 90.0, 1e-7);
}

// Fading enters as speckled power P Y, which is equation 21's
// G_fad = (255/X) gamma log10(Y); off means Y = 1.
TEST(Greytone, FadingTermIsEquation21) {
  const GreytoneMap map = make_greytone_map(radar_with(), {});
  const double p = 1e-10;
  for (double y : {0.01, 0.3, 1.0, 2.7}) {
    EXPECT_NEAR(map.greytone(p * y) - map.greytone(p), 255.0 / 2.5 * 0.8 * std::log10(y), kTol);
  }
}

TEST(Greytone, RoundThenClamp) {
  const RadarParams r = radar_with("[film.terms]\nk = false\nm = false\n");
  const GreytoneMap map = make_greytone_map(r, {});
  const double step = map.greytones_per_decade();
  auto power_for = [&](double g) {
    return map.reference_power_w() * std::pow(10.0, (g - 90.0) / step);
  };
  EXPECT_EQ(map.quantised(power_for(100.49)), 100);
  EXPECT_EQ(map.quantised(power_for(100.51)), 101);
  EXPECT_EQ(map.quantised(power_for(254.6)), 255);
  EXPECT_EQ(map.quantised(power_for(400.0)), 255);
  EXPECT_EQ(map.quantised(power_for(0.4)), 0);
  EXPECT_EQ(map.quantised(power_for(-30.0)), 0);
  EXPECT_EQ(map.quantised(0.0), 0);  // shadow: black
  EXPECT_EQ(map.quantised(std::numeric_limits<double>::quiet_NaN()), 0);
}

// The table lookup gives quantised() on every float tried: each threshold
// and its neighbours, a sweep over 40 decades around the reference, and
// special values.
TEST(Greytone, FastQuantisedEqualsQuantisedOnEveryFloatTried) {
  for (const char* extra : {"", "[film.terms]\nk = false\nm = false\n"}) {
    const GreytoneMap map = make_greytone_map(radar_with(extra), {});
    const auto check = [&](float p) {
      ASSERT_EQ(map.quantised_fast(p), map.quantised(double(p))) << p;
    };
    std::vector<int> seen(256, 0);
    for (int k = 0; k <= 2000000; ++k) {
      const double g = -200.0 + 600.0 * k / 2000000.0;
      const auto p = static_cast<float>(map.reference_power_w() *
                                        std::pow(10.0, (g - 128.0) / map.greytones_per_decade()));
      check(p);
      check(std::nextafter(p, 0.0f));
      check(std::nextafter(p, 1.0f));
      seen[map.quantised_fast(p)] = 1;
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), 256) << "the sweep makes every greytone";
    for (float p : {0.0f, -0.0f, -1.0f, std::numeric_limits<float>::denorm_min(),
                    std::numeric_limits<float>::min(), std::numeric_limits<float>::max(),
                    std::numeric_limits<float>::infinity()}) {
      check(p);
    }
  }
}

// greytone_line (the render's row kernel, with its fixed number of threshold
// steps and no branch on the power) gives quantised() on every float of the
// sweep above, special values included, and the no-data greytone where the
// power is NaN or the mask has one of the bits; also for a steep film whose
// 0.5% buckets hold several greytones each (more than one step).
TEST(Greytone, LineKernelEqualsQuantisedWithMask) {
  const std::string steep =
      kRadar.substr(0, kRadar.find("[film]")) + "[film]\ndensity_range = 0.3\ngamma = 3.0\n";
  for (const RadarParams& radar : {radar_with(), radar_from_toml(toml::parse(steep), "r.toml")}) {
    const GreytoneMap map = make_greytone_map(radar, {});
    std::vector<float> p;
    for (int k = 0; k <= 200000; ++k) {
      const double g = -200.0 + 600.0 * k / 200000.0;
      const auto v = static_cast<float>(map.reference_power_w() *
                                        std::pow(10.0, (g - 128.0) / map.greytones_per_decade()));
      p.insert(p.end(), {v, std::nextafter(v, 0.0f), std::nextafter(v, 1.0f)});
    }
    p.insert(p.end(),
             {0.0f, -0.0f, -1.0f, std::numeric_limits<float>::denorm_min(),
              std::numeric_limits<float>::min(), std::numeric_limits<float>::max(),
              std::numeric_limits<float>::infinity(), -std::numeric_limits<float>::infinity(),
              std::numeric_limits<float>::quiet_NaN()});
    std::vector<std::uint8_t> mask(p.size());
    for (std::size_t i = 0; i < mask.size(); ++i) mask[i] = static_cast<std::uint8_t>(i % 7);
    std::vector<std::uint8_t> out(p.size()), out_unmasked(p.size());
    greytone_line(map, p.data(), mask.data(), 4, p.size(), out.data(), 7);
    greytone_line(map, p.data(), nullptr, 4, p.size(), out_unmasked.data(), 7);
    std::vector<int> seen(256, 0);
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::uint8_t q = std::isnan(p[i]) ? 7 : map.quantised(double(p[i]));
      ASSERT_EQ(out_unmasked[i], q) << p[i];
      ASSERT_EQ(out[i], (mask[i] & 4) ? 7 : q) << p[i];
      seen[q] = 1;
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), 256);
  }
}

TEST(Greytone, AutoReferenceMapsTheMedianToTheGivenGreytone) {
  const std::string text =
      kRadar.substr(0, kRadar.find("[reference]")) + "[reference]\nauto = true\ngreytone = 140\n";
  const RadarParams r = radar_from_toml(toml::parse(text), "r.toml");
  ASSERT_TRUE(r.reference.automatic);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  // Valid: 1, 2, 4, 8, 100 (median 4); zeros, NaN and the masked 1e6 are excluded.
  const std::vector<float> p = {1, 0, 2, nan, 4, 8, 100, 0, 1e6f};
  std::vector<std::uint8_t> mask(p.size(), 0);
  mask[8] = 1;
  EXPECT_DOUBLE_EQ(median_valid_power_w(p, mask), 4.0);
  EXPECT_DOUBLE_EQ(median_valid_power_w(std::vector<float>{1, 2, 4, 8}), 3.0);  // even count
  const GreytoneMap map = make_greytone_map(r, p, mask);
  EXPECT_DOUBLE_EQ(map.reference_power_w(), 4.0);
  EXPECT_EQ(map.quantised(4.0), 140);
  std::vector<std::uint8_t> g(p.size());
  greytones(p, g, map, mask, 7);
  EXPECT_EQ(g[4], 140);
  EXPECT_EQ(g[1], 0);  // zero power: black
  EXPECT_EQ(g[3], 7);  // NaN: no data
  EXPECT_EQ(g[8], 7);  // masked
  EXPECT_EQ(g[5], map.quantised(8.0));
  // Nothing valid: an input error naming the reference.
  const std::vector<float> empty = {0, nan};
  EXPECT_THROW(make_greytone_map(r, empty), InputError);
}

// A sigma0 reference given as category + incidence is evaluated in the lut.
class TwoCategories final : public Sigma0Source {
 public:
  bool has_category(std::uint16_t c) const override { return c == 1 || c == 2; }
  double sigma0(std::uint16_t c, double theta, const RadarBand&) const override {
    return c * 0.01 * std::cos(theta);
  }
  std::string category_name(std::uint16_t c) const override { return std::to_string(c); }
  std::string description() const override { return "test"; }
};

TEST(Greytone, ReferenceSigma0FromCategoryAndAngle) {
  std::string text = kRadar;
  text.replace(text.find("sigma0_db = -12"), 15, "category = 2\nincidence = 60");
  RadarParams r = radar_from_toml(toml::parse(text), "r.toml");
  EXPECT_TRUE(std::isnan(r.reference.sigma0));
  const std::vector<std::uint16_t> cats = {1, 2};
  const Sigma0Lut lut = Sigma0Lut::build(TwoCategories(), {}, cats, "t.csv");
  resolve_reference_sigma0(r, lut);
  EXPECT_NEAR(r.reference.sigma0, 0.02 * 0.5, 1e-6);
  r.reference.sigma0_category = 3;
  EXPECT_THROW(resolve_reference_sigma0(r, lut), InputError);
}

TEST(Greytone, ConstantSigma0ForTheBackscatterSwitch) {
  const ConstantSigma0 c(0.05);
  EXPECT_TRUE(c.has_category(9));
  EXPECT_DOUBLE_EQ(c.sigma0(9, 0.3, {}), 0.05);
  const std::vector<std::uint16_t> cats = {0, 4};
  const Sigma0Lut lut = Sigma0Lut::build(c, {}, cats, "constant");
  EXPECT_NEAR(lut.at(4, 1.2f), 0.05f, 1e-7);
}

TEST(Greytone, RasterMatchesThePixelMap) {
  const GreytoneMap map = make_greytone_map(radar_with(), {});
  std::vector<float> p(100000);
  for (size_t i = 0; i < p.size(); ++i)
    p[i] = static_cast<float>(1e-14 * std::pow(1.0001, double(i)));
  std::vector<std::uint8_t> g(p.size());
  greytones(p, g, map);
  for (size_t i = 0; i < p.size(); i += 997) EXPECT_EQ(g[i], map.quantised(p[i]));
}

}  // namespace
}  // namespace ris

namespace ris {
namespace {

TEST(GreytoneImage, ChainWithAndWithoutFading) {
  constexpr int kLines = 50, kBins = 30;
  std::vector<float> mean(static_cast<size_t>(kLines) * kBins);
  for (size_t i = 0; i < mean.size(); ++i)
    mean[i] = static_cast<float>(1e-12 * static_cast<double>(1 + i % 7));
  std::vector<std::uint8_t> mask(mean.size(), 0);
  mask[3] = 1;
  const std::string auto_ref = kRadar.substr(0, kRadar.find("[reference]")) + "[film]\n";
  // Fading off: the speckled power is the mean power.
  const RadarParams off = radar_from_toml(toml::parse(auto_ref + "terms.fading = false\n"), "r");
  const GreytoneImage a = make_greytone_image(off, mean, kLines, kBins, 15000.0, 15.0, 1, mask);
  EXPECT_TRUE(std::isnan(a.speckled_power_w[3]));
  EXPECT_EQ(a.greytone[3], 0);
  for (size_t i = 4; i < mean.size(); ++i) {
    ASSERT_EQ(a.speckled_power_w[i], mean[i]);
    ASSERT_EQ(a.greytone[i], a.map.quantised(mean[i]));
  }
  EXPECT_EQ(a.map.quantised(median_valid_power_w(mean, mask)), 128);
  ASSERT_EQ(a.looks_per_bin.size(), static_cast<size_t>(kBins));
  EXPECT_DOUBLE_EQ(a.looks_per_bin[7], independent_samples(off, 15000.0 + 7.5 * 15.0));
  // Fading on: same reference (from the mean power), speckled pixels differ,
  // and the seed fixes them.
  const RadarParams on = radar_from_toml(toml::parse(auto_ref), "r");
  const GreytoneImage b = make_greytone_image(on, mean, kLines, kBins, 15000.0, 15.0, 1, mask);
  const GreytoneImage c = make_greytone_image(on, mean, kLines, kBins, 15000.0, 15.0, 1, mask);
  EXPECT_DOUBLE_EQ(b.map.reference_power_w(), a.map.reference_power_w());
  EXPECT_NE(b.speckled_power_w[10], mean[10]);
  EXPECT_EQ(b.greytone, c.greytone);
}

}  // namespace
}  // namespace ris
