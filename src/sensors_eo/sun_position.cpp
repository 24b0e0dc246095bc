#include "ris/sensors_eo/sun_position.h"

#include <cmath>
#include <numbers>

namespace ris {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

double wrap_360(double a) {
  a = std::fmod(a, 360.0);
  return a < 0 ? a + 360.0 : a;
}

// NOAA's atmospheric refraction fit (spreadsheet column AE), degrees, for a
// geometric elevation in degrees; standard atmosphere (1010 hPa, 10 C).
double refraction_deg(double elevation_deg) {
  if (elevation_deg > 85.0) return 0.0;
  const double te = std::tan(elevation_deg * kDeg);
  double arcsec = 0;
  if (elevation_deg > 5.0) {
    arcsec = 58.1 / te - 0.07 / (te * te * te) + 0.000086 / std::pow(te, 5);
  } else if (elevation_deg > -0.575) {
    const double e = elevation_deg;
    arcsec = 1735.0 + e * (-518.2 + e * (103.4 + e * (-12.79 + e * 0.711)));
  } else {
    arcsec = -20.772 / te;
  }
  return arcsec / 3600.0;
}

}  // namespace

double julian_day(const UtcDateTime& t) {
  int y = t.year;
  int m = t.month;
  if (m <= 2) {
    y -= 1;
    m += 12;
  }
  const int a = y / 100;
  const int b = 2 - a + a / 4;  // Gregorian correction
  return std::floor(365.25 * (y + 4716)) + std::floor(30.6001 * (m + 1)) + t.day + b - 1524.5 +
         t.hour / 24.0;
}

SunPosition sun_position(const UtcDateTime& t, double lat_deg, double lon_deg) {
  // Julian centuries since J2000.0; the spreadsheet uses UT for TT (the
  // ~70 s difference moves the sun by < 0.001 deg).
  const double jc = (julian_day(t) - 2451545.0) / 36525.0;
  const double l0 = wrap_360(280.46646 + jc * (36000.76983 + jc * 0.0003032));  // mean longitude
  const double m = 357.52911 + jc * (35999.05029 - 0.0001537 * jc);             // mean anomaly
  const double e = 0.016708634 - jc * (0.000042037 + 0.0000001267 * jc);        // eccentricity
  const double c = std::sin(m * kDeg) * (1.914602 - jc * (0.004817 + 0.000014 * jc)) +
                   std::sin(2 * m * kDeg) * (0.019993 - 0.000101 * jc) +
                   std::sin(3 * m * kDeg) * 0.000289;  // equation of centre
  const double true_long = l0 + c;
  const double true_anom = m + c;
  const double omega = 125.04 - 1934.136 * jc;  // longitude of the Moon's node (nutation)
  const double app_long = true_long - 0.00569 - 0.00478 * std::sin(omega * kDeg);
  const double mean_obliq =
      23.0 + (26.0 + (21.448 - jc * (46.815 + jc * (0.00059 - jc * 0.001813))) / 60.0) / 60.0;
  const double obliq = mean_obliq + 0.00256 * std::cos(omega * kDeg);

  SunPosition s;
  s.earth_sun_distance_au = 1.000001018 * (1 - e * e) / (1 + e * std::cos(true_anom * kDeg));
  const double decl = std::asin(std::sin(obliq * kDeg) * std::sin(app_long * kDeg));
  s.declination_deg = decl / kDeg;
  const double yv = std::pow(std::tan(obliq * kDeg / 2), 2);
  const double l0r = l0 * kDeg;
  const double mr = m * kDeg;
  s.equation_of_time_min = 4.0 / kDeg *
                           (yv * std::sin(2 * l0r) - 2 * e * std::sin(mr) +
                            4 * e * yv * std::sin(mr) * std::cos(2 * l0r) -
                            0.5 * yv * yv * std::sin(4 * l0r) - 1.25 * e * e * std::sin(2 * mr));
  const double true_solar_min =
      std::fmod(t.hour * 60.0 + s.equation_of_time_min + 4.0 * lon_deg, 1440.0);
  const double tst = true_solar_min < 0 ? true_solar_min + 1440.0 : true_solar_min;
  const double hour_angle = tst / 4.0 - 180.0;

  const double lat = lat_deg * kDeg;
  double cos_z =
      std::sin(lat) * std::sin(decl) + std::cos(lat) * std::cos(decl) * std::cos(hour_angle * kDeg);
  cos_z = std::fmax(-1.0, std::fmin(1.0, cos_z));
  const double zen = std::acos(cos_z);
  s.geometric_zenith_deg = zen / kDeg;
  const double refr = refraction_deg(90.0 - s.geometric_zenith_deg);
  s.zenith_deg = s.geometric_zenith_deg - refr;
  s.elevation_deg = 90.0 - s.zenith_deg;

  const double denom = std::cos(lat) * std::sin(zen);
  double az = 0;
  if (std::fabs(denom) > 1e-12) {
    double ca = (std::sin(lat) * std::cos(zen) - std::sin(decl)) / denom;
    ca = std::fmax(-1.0, std::fmin(1.0, ca));
    const double a = std::acos(ca) / kDeg;
    az = hour_angle > 0 ? wrap_360(a + 180.0) : wrap_360(540.0 - a);
  }
  s.azimuth_deg = az;
  return s;
}

}  // namespace ris
