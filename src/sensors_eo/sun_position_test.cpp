#include "ris/sensors_eo/sun_position.h"

#include <gtest/gtest.h>

namespace ris {
namespace {

// Reda & Andreas (2004), "Solar position algorithm for solar radiation
// applications", Solar Energy 76, 577-589, table A5.1 example: 2003-10-17
// 12:30:30 local (UTC-7) = 19:30:30 UTC, 39.742476 N, 105.1786 W:
// topocentric zenith 50.11162 deg (refracted), azimuth 194.34024 deg.
TEST(SunPosition, RedaAndreasSpaExampleWithin005Deg) {
  const UtcDateTime t{2003, 10, 17, 19.0 + 30.0 / 60.0 + 30.0 / 3600.0};
  const SunPosition s = sun_position(t, 39.742476, -105.1786);
  EXPECT_NEAR(s.zenith_deg, 50.11162, 0.05);
  EXPECT_NEAR(s.azimuth_deg, 194.34024, 0.05);
  EXPECT_NEAR(s.elevation_deg + s.zenith_deg, 90.0, 1e-12);
}

// Meeus (1991) example 7.a: 1957 Oct 4.81 = JD 2436116.31.
TEST(SunPosition, JulianDayMeeusExample) {
  EXPECT_NEAR(julian_day({1957, 10, 4, 0.81 * 24.0}), 2436116.31, 1e-6);
  EXPECT_NEAR(julian_day({2000, 1, 1, 12.0}), 2451545.0, 1e-9);
}

// Near the June solstice the declination is +23.44 deg (obliquity) and at
// local solar noon on the equator the sun stands due north at zenith ~23.4.
TEST(SunPosition, SolsticeDeclinationAndNoonAzimuth) {
  const SunPosition s = sun_position({2024, 6, 20, 12.0}, 0.0, 0.0);
  EXPECT_NEAR(s.declination_deg, 23.44, 0.02);
  // Perihelion in early January, aphelion in early July: r ~ 1.0167 au.
  EXPECT_NEAR(s.earth_sun_distance_au, 1.0163, 0.001);
  const SunPosition n = sun_position({2024, 6, 20, 12.0 - s.equation_of_time_min / 60.0}, 0.0, 0.0);
  EXPECT_NEAR(n.geometric_zenith_deg, 23.44, 0.02);
  EXPECT_TRUE(n.azimuth_deg < 1.0 || n.azimuth_deg > 359.0) << n.azimuth_deg;
}

TEST(SunPosition, MidnightIsBelowHorizonAtMidLatitude) {
  const SunPosition s = sun_position({2024, 3, 20, 0.0}, 48.0, 11.0);
  EXPECT_LT(s.elevation_deg, -30.0);
}

}  // namespace
}  // namespace ris
