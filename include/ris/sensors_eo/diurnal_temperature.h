// Diurnal surface temperature of a homogeneous half-space (the ground) under
// periodic surface forcing: the closed-form periodic solution of the 1-D heat
// equation (Carslaw & Jaeger 1959, "Conduction of Heat in Solids", 2nd ed.,
// sec. 2.6; as used for remote sensing by Price 1977, "Thermal inertia
// mapping", J. Geophys. Res. 82(18), 2582-2590).
//
// For a forcing harmonic F_n e^{i n w t} [W m^-2] absorbed at the surface and
// a loss linearised about the mean temperature, h (T - T_mean) with
// h = 4 eps sigma T_mean^3 (Price 1977's linearisation), the surface
// temperature harmonic is
//   T_n = F_n / (P sqrt(n w) e^{i pi/4} + h),
// P = sqrt(k rho c) the thermal inertia [J m^-2 K^-1 s^-1/2]. With h = 0 the
// amplitude is F_n / (P sqrt(n w)) and the lag is exactly pi/4 (3 h for the
// daily harmonic). docs/sensors.md, "Thermal".
#pragma once

#include <complex>
#include <vector>

#include "ris/sensors_eo/sun_position.h"

namespace ris {

// Absorbed-flux forcing per unit absorptance: the horizontal insolation
// E0 / r^2 * max(cos zenith, 0) over one UTC day, as its mean and first
// harmonics: I(t) = mean + sum_n Re(c_n e^{i n w t}), t in seconds of the day.
struct DiurnalForcing {
  double mean_w_m2 = 0;
  std::vector<std::complex<double>> harmonics_w_m2;  // n = 1, 2, ...
};

// Solar constant 1361 W m^-2 (Kopp & Lean 2011, Geophys. Res. Lett. 38,
// L01706). Sampled each minute of the day (year, month, day of `date`) with
// sun_position; no atmosphere (the transmittance multiplies it).
DiurnalForcing solar_forcing(const UtcDateTime& date, double lat_deg, double lon_deg,
                             int harmonics = 8, double transmittance = 1.0);

struct ThermalSurface {
  double mean_temperature_k = 288.0;
  double thermal_inertia = 1500.0;  // J m^-2 K^-1 s^-1/2
  double albedo = 0.2;              // broadband solar
  double emissivity = 0.95;         // broadband thermal, for the linearised loss
};

// The linearised radiative loss coefficient 4 eps sigma T^3 [W m^-2 K^-1].
double linearised_loss_w_m2_k(double emissivity, double temperature_k);

// Surface temperature [K] at t_seconds of the UTC day: T_mean plus the
// periodic response to (1 - albedo) x the forcing's harmonics (the mean flux
// is taken as balanced at T_mean).
double surface_temperature_k(const ThermalSurface& s, const DiurnalForcing& f, double t_seconds);

}  // namespace ris
