// The sun's position in the sky from date, time (UTC) and place.
//
// Algorithm: NOAA Global Monitoring Laboratory "Solar Calculator" spreadsheet
// (NOAA_Solar_Calculations_day.xls), which implements Meeus, "Astronomical
// Algorithms" (1991), ch. 25 (low-accuracy solar coordinates) with NOAA's
// refraction fit. Stated accuracy: about 0.01 deg in position for years
// 1800..2100 (ignoring the refraction model). docs/sensors.md, "Sun position".
#pragma once

namespace ris {

struct UtcDateTime {
  int year = 2000;
  int month = 1;    // 1..12
  int day = 1;      // 1..31
  double hour = 0;  // UTC hours incl. fraction, 0..24
};

struct SunPosition {
  double zenith_deg = 0;            // apparent (refracted) zenith angle
  double elevation_deg = 0;         // apparent elevation = 90 - zenith
  double geometric_zenith_deg = 0;  // without refraction
  double azimuth_deg = 0;           // clockwise from true north, 0..360
  double declination_deg = 0;
  double earth_sun_distance_au = 1;
  double equation_of_time_min = 0;
};

// Julian day (UT) of a Gregorian calendar date and time (Meeus 1991, ch. 7).
double julian_day(const UtcDateTime& t);

// lat_deg north positive, lon_deg east positive.
SunPosition sun_position(const UtcDateTime& t, double lat_deg, double lon_deg);

}  // namespace ris
