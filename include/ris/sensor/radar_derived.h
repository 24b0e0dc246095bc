// Quantities that follow from a radar description over flat ground at the
// scene datum (MODEL.md section 2): resolutions, the swath in slant and ground
// range, depression angles, the azimuth footprint and the number of
// independent samples N of the seed's equation 16. `ris radar info` prints
// them; the simulation's metadata records them.
//
// Equation 16 (seed report, section 2.1, after Moore):
//   N = 2 w / L = 2 h' phi^2 / (lambda cos theta)
// with w = h' phi / cos theta the azimuth resolution (the seed's equation 2
// with theta_A = 0) and L = lambda / phi the antenna length. The seed calls h'
// the "effective altitude"; in its equation 2 h' is "the height difference
// between the cell and the radar", H - h. Hence h' / cos theta is the slant
// range R and N = 2 R phi^2 / lambda: N grows linearly with range. For the
// seed's figure-4-5 radar N is about 0.95 at near range and 1.10 at far range,
// i.e. single-look imagery; a pixel cannot hold fewer than one independent
// sample, so independent_samples() never returns less than 1.
//
// Example:
//   ris::RadarDerived d = ris::derive(radar);
//   fmt::print("{} bins, near depression {:.2f} deg\n", d.range_bins,
//              ris::rad_to_deg(d.near_depression_rad));
#pragma once

#include "ris/sensor/radar_params.h"

namespace ris {

struct RadarDerived {
  double wavelength_m = 0.0;
  double range_resolution_m = 0.0;  // c tau / 2 (SAR: c / (2 B), single look)
  double range_bin_m = 0.0;         // as configured (default c tau / 2)
  int range_bins = 0;
  double near_slant_range_m = 0.0, far_slant_range_m = 0.0;
  double near_ground_range_m = 0.0, far_ground_range_m = 0.0;  // sqrt(R^2 - H^2)
  double swath_ground_m = 0.0;                                 // far - near ground range
  double near_depression_rad = 0.0, far_depression_rad = 0.0;  // asin(H / R)
  double near_incidence_rad = 0.0, far_incidence_rad = 0.0;    // 90 deg - depression
  double near_azimuth_footprint_m = 0.0;  // R phi (SAR: L_a rho_a at every range)
  double far_azimuth_footprint_m = 0.0;
  double near_samples_eq16 = 0.0, far_samples_eq16 = 0.0;  // raw equation 16
  double near_samples = 0.0, far_samples = 0.0;            // as used for fading
  bool samples_from_eq16 = true;
  // Only when speed and PRF are given (0 otherwise): pulses per azimuth
  // footprint, PRF w / v, at near and far range.
  double near_pulses_per_footprint = 0.0, far_pulses_per_footprint = 0.0;
};

RadarDerived derive(const RadarParams& radar);

// Flat-ground geometry helpers, for an altitude H above the datum.
double ground_range_m(double slant_range_m, double altitude_m);  // sqrt(R^2 - H^2), 0 if R < H
double depression_rad(double slant_range_m, double altitude_m);  // asin(H / R)

// The seed's equation 16 as written: N = 2 h' phi^2 / (lambda cos theta) with
// h' / cos theta = R, i.e. 2 R phi^2 / lambda. May be below 1.
double independent_samples_eq16(double slant_range_m, double beamwidth_rad, double wavelength_m);

// N used for fading at slant range R: the configured number, or equation 16
// at R, never less than 1.
double independent_samples(const RadarParams& radar, double slant_range_m);

}  // namespace ris
