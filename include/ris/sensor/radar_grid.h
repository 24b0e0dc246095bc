// The radar grid of an acquisition: which zero-Doppler time each image line
// and which slant range each range bin stands for (ISCE3's
// RadarGridParameters). Line l is at t0 + l * dt, bin b at R0 + b * dR;
// fractional lines and bins are positions between sample centres.
#pragma once

#include "ris/sensor/look_side.h"

namespace ris {

struct RadarGrid {
  double sensing_start_s = 0.0;  // zero-Doppler time of line 0, s since the orbit epoch
  double line_interval_s = 0.0;  // zero-Doppler time between lines
  int lines = 0;
  double near_range_m = 0.0;     // slant range of bin 0 (one way)
  double range_spacing_m = 0.0;  // slant range between bins
  int bins = 0;
  LookSide look_side = LookSide::right;
  double wavelength_m = 0.0;
  double prf_hz = 0.0;  // the pulse repetition frequency (for Doppler tolerances)

  double time_of_line(double line) const { return sensing_start_s + line * line_interval_s; }
  double range_of_bin(double bin) const { return near_range_m + bin * range_spacing_m; }
  double line_of_time(double t_s) const { return (t_s - sensing_start_s) / line_interval_s; }
  double bin_of_range(double r_m) const { return (r_m - near_range_m) / range_spacing_m; }
  double end_s() const { return time_of_line(lines - 1); }
  double far_range_m() const { return range_of_bin(bins - 1); }
};

}  // namespace ris
