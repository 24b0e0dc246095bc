// Blackbody radiance over a spectral band and its inverse (brightness
// temperature). Planck's law in wavelength,
//   B(lambda, T) = 2 h c^2 / lambda^5 / (exp(h c / (lambda k T)) - 1)
// [W m^-2 sr^-1 m^-1], integrated over [lambda_lo, lambda_hi] in closed form
// with the series of Widger & Woodall (1976), "Integration of the Planck
// blackbody radiation function", Bull. Am. Meteorol. Soc. 57(10), 1217-1219.
// Constants: CODATA 2018 (exact SI values of h, c, k). docs/sensors.md.
#pragma once

namespace ris {

struct SpectralBand {
  double lambda_lo_m = 0;
  double lambda_hi_m = 0;
};

// Spectral radiance at one wavelength [W m^-2 sr^-1 m^-1].
double planck_spectral_radiance(double lambda_m, double temperature_k);

// Radiance from 0 to lambda_m [W m^-2 sr^-1] (the Widger-Woodall series).
double planck_radiance_below(double lambda_m, double temperature_k);

// Band radiance [W m^-2 sr^-1] (closed form: difference of two series).
double planck_band_radiance(const SpectralBand& band, double temperature_k);

// The same by composite Simpson quadrature of planck_spectral_radiance with
// `intervals` (even) sub-intervals; for tests and as a check.
double planck_band_radiance_simpson(const SpectralBand& band, double temperature_k, int intervals);

// The temperature whose blackbody band radiance is radiance_w_m2_sr (the
// brightness temperature). Throws std::invalid_argument for radiance <= 0.
// Bisection on the monotone band radiance, to ~1e-12 relative.
double brightness_temperature_k(const SpectralBand& band, double radiance_w_m2_sr);

// Total radiance sigma T^4 / pi (Stefan-Boltzmann).
double blackbody_total_radiance(double temperature_k);

}  // namespace ris
