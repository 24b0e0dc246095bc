#include "ris/sensors_eo/planck_band.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

namespace ris {
namespace {

constexpr double kH = 6.62607015e-34;  // Planck constant [J s], exact (SI 2019)
constexpr double kC = 299792458.0;     // speed of light [m/s], exact
constexpr double kK = 1.380649e-23;    // Boltzmann constant [J/K], exact
constexpr double kC2 = kH * kC / kK;   // second radiation constant [m K]

}  // namespace

double planck_spectral_radiance(double lambda_m, double temperature_k) {
  const double x = kC2 / (lambda_m * temperature_k);
  return 2.0 * kH * kC * kC / std::pow(lambda_m, 5) / std::expm1(x);
}

double planck_radiance_below(double lambda_m, double temperature_k) {
  if (lambda_m <= 0) return 0.0;
  // Radiance from 0 to lambda equals the wavenumber integral from 1/lambda
  // to infinity: 2 h c^2 (kT/hc)^4 sum_n e^{-nx} (x^3/n + 3x^2/n^2 + 6x/n^3 + 6/n^4),
  // x = c2 / (lambda T) (Widger & Woodall 1976, eq. 5). Terms fall as e^{-nx};
  // enough of them that e^{-nx}/n^4 < 1e-17 of the sum's first term.
  const double x = kC2 / (lambda_m * temperature_k);
  const int terms = x > 0.5 ? static_cast<int>(2.0 + 40.0 / x) : 2000;
  // e^{-nx} as powers of e^{-x}: one exponential per call, not one per term
  // (the per-cell thermal image evaluates this millions of times). Summed
  // from n = 1 up: the powers only shrink (no overflow of e^{+x} steps, no
  // underflow of a first e^{-2000 x}); the terms fall fast enough that the
  // order costs nothing measurable (the tests' 1e-9 against Simpson).
  const double q = std::exp(-x);
  double qn = 1.0;
  double sum = 0;
  for (int n = 1; n <= terms; ++n) {
    const double dn = n;
    qn *= q;
    sum += qn * (x * x * x / dn + 3 * x * x / (dn * dn) + 6 * x / (dn * dn * dn) +
                 6 / (dn * dn * dn * dn));
  }
  const double kt_hc = kK * temperature_k / (kH * kC);
  const double kt_hc2 = kt_hc * kt_hc;
  return 2.0 * kH * kC * kC * kt_hc2 * kt_hc2 * sum;
}

double planck_band_radiance(const SpectralBand& band, double temperature_k) {
  return planck_radiance_below(band.lambda_hi_m, temperature_k) -
         planck_radiance_below(band.lambda_lo_m, temperature_k);
}

double planck_band_radiance_simpson(const SpectralBand& band, double temperature_k, int intervals) {
  const int n = intervals + (intervals % 2);
  const double h = (band.lambda_hi_m - band.lambda_lo_m) / n;
  double s = planck_spectral_radiance(band.lambda_lo_m, temperature_k) +
             planck_spectral_radiance(band.lambda_hi_m, temperature_k);
  for (int i = 1; i < n; ++i) {
    s += (i % 2 ? 4.0 : 2.0) * planck_spectral_radiance(band.lambda_lo_m + i * h, temperature_k);
  }
  return s * h / 3.0;
}

double brightness_temperature_k(const SpectralBand& band, double radiance_w_m2_sr) {
  if (!(radiance_w_m2_sr > 0)) {
    throw std::invalid_argument("brightness temperature needs a positive band radiance");
  }
  // Newton's method on B(T) - L, kept inside a bracket [lo, hi] that every
  // step narrows (a step leaving it bisects instead): the band radiance
  // rises monotonically with T. From the monochromatic inverse at the band's
  // centre it converges in 3-5 steps (bisection alone took ~45 steps, each
  // two Widger-Woodall series: the per-cell thermal image spent most of its
  // time here).
  const double centre = 0.5 * (band.lambda_lo_m + band.lambda_hi_m);
  const double width = band.lambda_hi_m - band.lambda_lo_m;
  const double spectral = radiance_w_m2_sr / width;
  double t = kC2 / (centre * std::log1p(2.0 * kH * kC * kC / (std::pow(centre, 5) * spectral)));
  double lo = 1.0;
  double hi = 1.0e5;
  if (!(t > lo && t < hi)) t = 300.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; ++i) {
    const double f = planck_band_radiance(band, t) - radiance_w_m2_sr;
    (f < 0 ? lo : hi) = t;
    const double dt = 1e-4 * t;
    const double slope =
        (planck_band_radiance(band, t + dt) - planck_band_radiance(band, t - dt)) / (2 * dt);
    const double next = slope > 0 ? t - f / slope : 0.5 * (lo + hi);
    if (std::abs(next - t) <= 1e-12 * t) return next;
    t = (next > lo && next < hi) ? next : 0.5 * (lo + hi);
  }
  return t;
}

double blackbody_total_radiance(double temperature_k) {
  // sigma = 2 pi^5 k^4 / (15 h^3 c^2)
  const double pi = std::numbers::pi;
  const double sigma = 2 * std::pow(pi, 5) * std::pow(kK, 4) / (15 * std::pow(kH, 3) * kC * kC);
  return sigma * std::pow(temperature_k, 4) / pi;
}

}  // namespace ris
