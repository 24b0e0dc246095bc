// Morchin's land clutter model against its closed form evaluated by hand
// (morchin.cpp's equations, Morchin 1990) and its validity checks.
#include <gtest/gtest.h>

#include <cmath>

#include "backscatter/models/models.h"
#include "ris/io/config_table.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris::detail {
namespace {

double db(double x) {
  return 10.0 * std::log10(x);
}

std::unique_ptr<BackscatterModel> morchin(const std::string& terrain) {
  static std::vector<toml::table> keep;  // the ConfigTable refers to its table
  keep.push_back(toml::parse("m = { name = \"morchin\", terrain = \"" + terrain + "\" }"));
  ConfigTable root(keep.back(), "test.toml", "");
  std::optional<ConfigTable> t = root.subtable("m");
  return make_backscatter_model(*t, ModelContext{"test.toml", ".", false, -1, nullptr});
}

// Mountains at 3 GHz, grazing 50 deg, by hand: lambda = c / f = 0.0999308 m,
// A sin(psi) / lambda = 0.04 x 0.7660444 / 0.0999308 = 0.3066299;
// mu = sqrt(3) / 4.7 = 0.3685214, cot^2(0.5) = 3.3506853,
// tan(1.24 - 0.8726646) = 0.3848008, its square over tan^2(0.5) = 0.4961416:
// exp(-0.4961416) = 0.6088754; specular 0.3685214 x 3.3506853 x 0.6088754
// = 0.7518390; sigma0 = 1.0584689 (+0.2468 dB).
TEST(Morchin, MountainsClosedFormByHand) {
  const auto m = morchin("mountains");
  const double s = m->sigma0(deg_to_rad(40.0), {3e9, Polarisation::VV});
  EXPECT_NEAR(s, 1.0584689, 2e-6);
  EXPECT_NEAR(s, morchin_sigma0(0.04, 1.24, 0.5, false, 3e9, deg_to_rad(50.0)), 1e-12);
}

// Farmland: B = pi/2, so at grazing psi the specular term is
// mu cot^2(b0) exp(-cot^2(psi) / tan^2(b0)): negligible at 30 deg
// (exp(-73)), dominant at vertical incidence (psi = 90 deg: mu cot^2 b0).
TEST(Morchin, FarmlandDiffuseAndSpecularLimits) {
  const auto m = morchin("farmland");
  const double f = 1.25e9;
  const double lambda = kSpeedOfLight_m_per_s / f;
  EXPECT_NEAR(m->sigma0(deg_to_rad(60.0), {f, Polarisation::HH}), 0.004 * 0.5 / lambda, 1e-9);
  const double mu = std::sqrt(1.25) / 4.7;
  const double cot2 = 1.0 / std::pow(std::tan(0.2), 2);
  EXPECT_NEAR(m->sigma0(0.0, {f, Polarisation::HH}), 0.004 / lambda + mu * cot2, 1e-9);
  EXPECT_EQ(m->sigma0(deg_to_rad(90.0), {f, Polarisation::HH}), 0.0);  // grazing 0
}

// Desert below its critical angle: h_e = 9.3 x 0.14^2.2 = 0.1230169 m; at
// 1 GHz lambda = 0.2997925 m, psi_c = asin(lambda / (4 pi h_e)) = 0.1951672
// rad (11.18 deg); at psi = 5 deg, sigma_c = psi / psi_c = 0.4471.
TEST(Morchin, DesertBelowTheCriticalAngle) {
  const auto m = morchin("desert");
  const double f = 1e9;
  const double lambda = kSpeedOfLight_m_per_s / f;
  const double h_e = 9.3 * std::pow(0.14, 2.2);
  EXPECT_NEAR(h_e, 0.1230169, 1e-6);
  const double psi_c = std::asin(lambda / (4.0 * kPi * h_e));
  EXPECT_NEAR(rad_to_deg(psi_c), 11.18, 0.01);
  const double psi = deg_to_rad(5.0);
  const double want = 0.00126 * (psi / psi_c) * std::sin(psi) / lambda;  // specular ~ 0
  EXPECT_NEAR(m->sigma0(kPi / 2.0 - psi, {f, Polarisation::HH}) / want, 1.0, 1e-9);
  // Above psi_c, sigma_c = 1.
  const double above = deg_to_rad(20.0);
  EXPECT_NEAR(m->sigma0(kPi / 2.0 - above, {f, Polarisation::HH}),
              0.00126 * std::sin(above) / lambda, 1e-12);
}

TEST(Morchin, UnknownTerrainAndBadBandsAreInputErrors) {
  EXPECT_THROW(morchin("tundra"), InputError);
  const auto m = morchin("farmland");
  EXPECT_THROW(m->check_band({9.6e9, Polarisation::HH}), InputError);
  EXPECT_THROW(m->check_band({0.2e9, Polarisation::HH}), InputError);
  EXPECT_THROW(m->check_band({5e9, Polarisation::VH}), InputError);
  EXPECT_NO_THROW(m->check_band({8e9, Polarisation::VV}));
  EXPECT_NEAR(db(m->sigma0(deg_to_rad(60.0), {5e9, Polarisation::HH})), -14.77, 0.01);
}

}  // namespace
}  // namespace ris::detail
