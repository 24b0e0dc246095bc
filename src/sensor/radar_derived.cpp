#include "ris/sensor/radar_derived.h"

#include <algorithm>
#include <cmath>

#include "ris/util/units.h"

namespace ris {

double ground_range_m(double slant_range_m, double altitude_m) {
  const double d = slant_range_m * slant_range_m - altitude_m * altitude_m;
  return d > 0.0 ? std::sqrt(d) : 0.0;
}

double depression_rad(double slant_range_m, double altitude_m) {
  return std::asin(std::clamp(altitude_m / slant_range_m, -1.0, 1.0));
}

double independent_samples_eq16(double slant_range_m, double beamwidth_rad, double wavelength_m) {
  return 2.0 * slant_range_m * beamwidth_rad * beamwidth_rad / wavelength_m;
}

double independent_samples(const RadarParams& radar, double slant_range_m) {
  if (radar.independent_samples) return *radar.independent_samples;
  return std::max(1.0, independent_samples_eq16(slant_range_m, radar.azimuth_beamwidth_rad,
                                                radar.wavelength_m()));
}

RadarDerived derive(const RadarParams& radar) {
  RadarDerived d;
  const double h_m = radar.track.altitude_m;
  const double phi = radar.azimuth_beamwidth_rad;
  d.wavelength_m = radar.wavelength_m();
  // SAR: c / (2 B) from the chirp bandwidth (single look); others: c tau / 2.
  d.range_resolution_m = radar.mode == RadarMode::sar
                             ? radar.sar.range_resolution_m
                             : kSpeedOfLight_m_per_s * radar.pulse_width_s / 2.0;
  d.range_bin_m = radar.range_bin_m;
  d.range_bins = radar.range_bins;
  d.near_slant_range_m = radar.near_slant_range_m;
  d.far_slant_range_m = radar.far_slant_range_m;
  d.near_ground_range_m = ground_range_m(d.near_slant_range_m, h_m);
  d.far_ground_range_m = ground_range_m(d.far_slant_range_m, h_m);
  d.swath_ground_m = d.far_ground_range_m - d.near_ground_range_m;
  d.near_depression_rad = depression_rad(d.near_slant_range_m, h_m);
  d.far_depression_rad = depression_rad(d.far_slant_range_m, h_m);
  d.near_incidence_rad = kPi / 2 - d.near_depression_rad;
  d.far_incidence_rad = kPi / 2 - d.far_depression_rad;
  // SAR: the (multilooked) azimuth resolution is the same at every range.
  const bool sar = radar.mode == RadarMode::sar;
  d.near_azimuth_footprint_m =
      sar ? radar.sar.azimuth_resolution_looks_m() : d.near_slant_range_m * phi;
  d.far_azimuth_footprint_m =
      sar ? radar.sar.azimuth_resolution_looks_m() : d.far_slant_range_m * phi;
  d.near_samples_eq16 = independent_samples_eq16(d.near_slant_range_m, phi, d.wavelength_m);
  d.far_samples_eq16 = independent_samples_eq16(d.far_slant_range_m, phi, d.wavelength_m);
  d.near_samples = independent_samples(radar, d.near_slant_range_m);
  d.far_samples = independent_samples(radar, d.far_slant_range_m);
  d.samples_from_eq16 = !radar.independent_samples.has_value();
  if (radar.speed_m_per_s > 0.0 && radar.prf_hz > 0.0) {
    d.near_pulses_per_footprint = radar.prf_hz * d.near_azimuth_footprint_m / radar.speed_m_per_s;
    d.far_pulses_per_footprint = radar.prf_hz * d.far_azimuth_footprint_m / radar.speed_m_per_s;
  }
  return d;
}

}  // namespace ris
