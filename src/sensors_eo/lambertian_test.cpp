#include "ris/sensors_eo/lambertian.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ris/sensors_eo/eo_band.h"
#include "ris/sensors_eo/sun_position.h"

namespace ris {
namespace {

// A horizontal Lambertian plane under the sun alone (no sky, no path,
// T = 1): L = rho E cos(theta_z) / pi at every sun zenith through the day.
TEST(Lambertian, PlaneFollowsCosineOfSunZenith) {
  const double e_sun = eo_band_info(EoBand::red).solar_irradiance_w_m2_um;
  for (double hour = 6.0; hour <= 18.0; hour += 0.5) {
    const SunPosition s = sun_position({2024, 6, 21, hour}, 48.0, 11.0);
    if (s.elevation_deg <= 0) continue;
    Illumination e;
    e.sun_irradiance_w_m2_um = e_sun;
    e.cos_incidence = std::cos(s.zenith_deg * std::numbers::pi / 180.0);
    const double expected = 0.3 * e_sun * e.cos_incidence / std::numbers::pi;
    EXPECT_NEAR(lambertian_radiance(0.3, e), expected, 1e-12 * e_sun) << hour;
  }
}

TEST(Lambertian, ShadowKeepsOnlySkyAndPath) {
  Illumination e;
  e.sun_irradiance_w_m2_um = 1500;
  e.cos_incidence = 0.8;
  e.transmittance_down = 0.7;
  e.transmittance_up = 0.9;
  e.sky_irradiance_w_m2_um = 100;
  e.path_radiance_w_m2_sr_um = 5;
  const double lit = lambertian_radiance(0.2, e);
  e.lit = false;
  const double dark = lambertian_radiance(0.2, e);
  EXPECT_NEAR(dark, 0.2 * 100 / std::numbers::pi * 0.9 + 5, 1e-12);
  EXPECT_NEAR(lit - dark, 0.2 * 1500 * 0.8 * 0.7 / std::numbers::pi * 0.9, 1e-12);
}

TEST(Lambertian, ThermalKirchhoff) {
  EXPECT_DOUBLE_EQ(thermal_leaving_radiance(1.0, 30.0, 10.0), 30.0);
  EXPECT_DOUBLE_EQ(thermal_leaving_radiance(0.0, 30.0, 10.0), 10.0);
  EXPECT_DOUBLE_EQ(thermal_leaving_radiance(0.9, 30.0, 10.0), 28.0);
}

}  // namespace
}  // namespace ris
