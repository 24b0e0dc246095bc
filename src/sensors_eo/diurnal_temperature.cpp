#include "ris/sensors_eo/diurnal_temperature.h"

#include <cmath>
#include <numbers>

namespace ris {
namespace {

constexpr double kSolarConstant = 1361.0;  // W m^-2, Kopp & Lean (2011)
constexpr double kSigma = 5.670374419e-8;  // W m^-2 K^-4, CODATA 2018
constexpr double kDaySeconds = 86400.0;

}  // namespace

DiurnalForcing solar_forcing(const UtcDateTime& date, double lat_deg, double lon_deg, int harmonics,
                             double transmittance) {
  constexpr int kSamples = 1440;
  const double w = 2 * std::numbers::pi / kDaySeconds;
  DiurnalForcing f;
  f.harmonics_w_m2.assign(static_cast<std::size_t>(harmonics), {0.0, 0.0});
  for (int i = 0; i < kSamples; ++i) {
    const double t = (i + 0.5) * kDaySeconds / kSamples;
    const SunPosition s =
        sun_position({date.year, date.month, date.day, t / 3600.0}, lat_deg, lon_deg);
    const double cz = std::cos(s.geometric_zenith_deg * std::numbers::pi / 180.0);
    const double insolation = cz > 0 ? transmittance * kSolarConstant * cz /
                                           (s.earth_sun_distance_au * s.earth_sun_distance_au)
                                     : 0.0;
    f.mean_w_m2 += insolation / kSamples;
    for (int n = 1; n <= harmonics; ++n) {
      // c_n = (2/N) sum I e^{-i n w t}, so I = mean + sum Re(c_n e^{i n w t}).
      f.harmonics_w_m2[n - 1] += 2.0 / kSamples * insolation * std::polar(1.0, -n * w * t);
    }
  }
  return f;
}

double linearised_loss_w_m2_k(double emissivity, double temperature_k) {
  return 4.0 * emissivity * kSigma * temperature_k * temperature_k * temperature_k;
}

double surface_temperature_k(const ThermalSurface& s, const DiurnalForcing& f, double t_seconds) {
  const double w = 2 * std::numbers::pi / kDaySeconds;
  const double h = linearised_loss_w_m2_k(s.emissivity, s.mean_temperature_k);
  const std::complex<double> lag = std::polar(1.0, std::numbers::pi / 4);
  double t = s.mean_temperature_k;
  for (std::size_t k = 0; k < f.harmonics_w_m2.size(); ++k) {
    const double wn = w * static_cast<double>(k + 1);
    const std::complex<double> tn =
        (1.0 - s.albedo) * f.harmonics_w_m2[k] / (s.thermal_inertia * std::sqrt(wn) * lag + h);
    t += std::real(tn * std::polar(1.0, wn * t_seconds));
  }
  return t;
}

}  // namespace ris
