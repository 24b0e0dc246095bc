// Golden case: ESA's own geolocation grid of the shipped Sentinel-1 IW SLC
// annotation (210 tie points with latitude, longitude, height, zero-Doppler
// azimuth time, two-way slant range time and incidence angle). ris's geo2rdr
// from the annotation's orbit must reproduce, at every tie point, the slant
// range within 0.5 m, the azimuth time within 0.2 ms and the incidence within
// 0.01 deg. The annotation's incidenceAngle is measured from the geocentric
// radius vector, so it is compared with incidence_geocentric_deg; the
// ellipsoid-normal incidence differs from it by ~0.03 deg at 42 N.
#include <gtest/gtest.h>

#include <cmath>

#include "acquisition_paths.h"
#include "ris/geometry/zero_doppler.h"
#include "ris/sensor/acquisition.h"
#include "ris/sensor/sentinel1_annotation.h"
#include "ris/util/units.h"

namespace ris {
namespace {

TEST(Sentinel1Geolocation, GeoToRadarMatchesTiePoints) {
  const Acquisition acq = read_acquisition(test::sentinel1_safe());
  const auto tie = read_sentinel1_tie_points(test::sentinel1_safe());
  ASSERT_EQ(tie.size(), 210U);
  double worst_r = 0.0, worst_t = 0.0, worst_inc = 0.0, min_diff = 1e9, max_diff = 0.0;
  for (const Sentinel1TiePoint& p : tie) {
    const Vec3 x =
        acq.ellipsoid.to_ecef({deg_to_rad(p.lat_deg), deg_to_rad(p.lon_deg), p.height_m});
    const double t_ref = p.azimuth_time.seconds_since(acq.orbit.epoch());
    const RadarPoint r = geo2rdr(acq.orbit, x, acq.grid.sensing_start_s);
    ASSERT_TRUE(r.converged);
    const LookAngles a = look_angles(acq.ellipsoid, r.sensor_m, x);
    worst_r = std::max(
        worst_r, std::abs(r.slant_range_m - p.slant_range_time_s * kSpeedOfLight_m_per_s / 2));
    worst_t = std::max(worst_t, std::abs(r.time_s - t_ref));
    worst_inc = std::max(worst_inc, std::abs(a.incidence_geocentric_deg - p.incidence_deg));
    const double d = std::abs(a.incidence_deg - a.incidence_geocentric_deg);
    min_diff = std::min(min_diff, d);
    max_diff = std::max(max_diff, d);
  }
  EXPECT_LT(worst_r, 0.5);     // the limit; measured 0.2 mm
  EXPECT_LT(worst_t, 0.2e-3);  // the limit; measured 1.5 us
  EXPECT_LT(worst_inc, 0.01);  // the limit; measured 6e-9 deg
  // The two conventions differ by 0.034-0.036 deg here.
  EXPECT_GT(min_diff, 0.03);
  EXPECT_LT(max_diff, 0.04);
  std::printf(
      "tie points: |dR| <= %.4f m, |dt| <= %.3g s, |dinc| <= %.2g deg; "
      "ellipsoid - geocentric %.4f..%.4f deg\n",
      worst_r, worst_t, worst_inc, min_diff, max_diff);
}

}  // namespace
}  // namespace ris
