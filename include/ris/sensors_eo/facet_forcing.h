// The day's solar forcing of one facet of the terrain (issue 35 item 3;
// docs/sensors.md "Thermal"): the insolation on a surface of normal n,
//   I(t) = T E_s / r^2 max(n . s(t), 0) lit(t),
// sampled over the UTC day (every 30 minutes) with the sun's direction s(t)
// from sun_position, lit(t) 0 while the facet is in a cast shadow (a ray to
// the sun through the terrain mesh), and reduced to its mean and first
// harmonics exactly as solar_forcing does for flat open ground
// (ris/sensors_eo/diurnal_temperature.h). A slope facing the sun, a wall
// lit all morning or a yard shaded at noon then heats as its own insolation
// says; the daily mean temperature stays the sensor's key for every facet
// (the model balances the mean flux at T_mean).
#pragma once

#include <complex>
#include <vector>

#include "ris/sensors_eo/diurnal_temperature.h"
#include "ris/sensors_eo/sun_position.h"
#include "ris/util/vec3.h"

namespace ris {

struct DaySamples {
  std::vector<double> t_seconds;
  std::vector<Vec3> sun_enu;            // unit vector to the sun (ENU)
  std::vector<double> irradiance_w_m2;  // T E_s / r^2 with the sun up, else 0
  // basis[k * harmonics + (n - 1)] = (2 / N) e^{-i n w t_k}
  std::vector<std::complex<double>> basis;
  int harmonics = 0;
};

// 48 samples (30 minutes) by default.
DaySamples day_samples(const UtcDateTime& date, double lat_deg, double lon_deg, int harmonics,
                       double transmittance, int samples = 48);

// Fills f (its harmonics resized once, so a caller reusing f allocates
// nothing per facet) from the insolation of each sample (W m^-2).
void forcing_from_insolation(const DaySamples& day, const double* insolation_w_m2,
                             DiurnalForcing& f);

}  // namespace ris
