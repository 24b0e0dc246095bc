#include "ris/sensors_eo/planck_band.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace ris {
namespace {

const SpectralBand kLwir{8e-6, 12e-6};
const SpectralBand kMwir{3e-6, 5e-6};

TEST(PlanckBand, SeriesMatchesSimpsonQuadrature) {
  for (double t : {250.0, 300.0, 350.0, 1000.0}) {
    for (const SpectralBand& b : {kLwir, kMwir}) {
      const double series = planck_band_radiance(b, t);
      const double simpson = planck_band_radiance_simpson(b, t, 4000);
      EXPECT_NEAR(series / simpson, 1.0, 1e-9) << t;
    }
  }
}

// The whole spectrum gives sigma T^4 / pi; sigma = 5.670374419e-8 W m^-2 K^-4
// (CODATA 2018).
TEST(PlanckBand, WholeSpectrumIsStefanBoltzmann) {
  const double t = 300.0;
  const double sigma_codata = 5.670374419e-8;
  EXPECT_NEAR(planck_radiance_below(1.0, t) / (sigma_codata * t * t * t * t / 3.141592653589793),
              1.0, 1e-6);
  EXPECT_NEAR(blackbody_total_radiance(t) / (sigma_codata * t * t * t * t / 3.141592653589793), 1.0,
              1e-9);
}

// Published blackbody fraction: F(0 -> lambda T = 2898 um K) = 0.250108
// (Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, table 12.1).
TEST(PlanckBand, PublishedBlackbodyFractionWithinPointOnePercent) {
  const double t = 1000.0;
  const double fraction = planck_radiance_below(2898e-6 / t, t) / blackbody_total_radiance(t);
  EXPECT_NEAR(fraction / 0.250108, 1.0, 1e-3);
}

TEST(PlanckBand, BrightnessTemperatureInvertsExactly) {
  for (double t : {200.0, 273.15, 300.0, 330.0, 600.0}) {
    for (const SpectralBand& b : {kLwir, kMwir}) {
      EXPECT_NEAR(brightness_temperature_k(b, planck_band_radiance(b, t)), t, 1e-8 * t);
    }
  }
}

TEST(PlanckBand, BrightnessTemperatureRefusesNonPositiveRadiance) {
  EXPECT_THROW(brightness_temperature_k(kLwir, 0.0), std::invalid_argument);
  EXPECT_THROW(brightness_temperature_k(kLwir, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace ris
