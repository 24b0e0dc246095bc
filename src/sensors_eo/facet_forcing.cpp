#include "ris/sensors_eo/facet_forcing.h"

#include <cmath>
#include <numbers>

#include "ris/sensors_eo/sun_shadow.h"

namespace ris {
namespace {

constexpr double kSolarConstant = 1361.0;  // W m^-2, Kopp & Lean (2011), as solar_forcing
constexpr double kDaySeconds = 86400.0;

}  // namespace

DaySamples day_samples(const UtcDateTime& date, double lat_deg, double lon_deg, int harmonics,
                       double transmittance, int samples) {
  // Each sample stands for its interval of the day: the fraction of the
  // interval with the sun up (from 16 sub-samples) scales the irradiance and
  // the sun's direction is the mean over the up part, so a wall lit from the
  // moment of sunrise is not over- or under-counted by up to half an
  // interval (6 % of its daily mean at 30-minute samples).
  constexpr int kSub = 16;
  DaySamples d;
  d.harmonics = harmonics;
  const double w = 2 * std::numbers::pi / kDaySeconds;
  const double step = kDaySeconds / samples;
  for (int i = 0; i < samples; ++i) {
    const double t = (i + 0.5) * step;
    Vec3 dir{};
    double up = 0, irradiance = 0;
    for (int j = 0; j < kSub; ++j) {
      const double tj = i * step + (j + 0.5) * step / kSub;
      const SunPosition s =
          sun_position({date.year, date.month, date.day, tj / 3600.0}, lat_deg, lon_deg);
      const double elevation = 90.0 - s.geometric_zenith_deg;
      if (elevation <= 0) continue;
      up += 1;
      dir += sun_direction_enu(s.azimuth_deg, elevation);
      irradiance +=
          transmittance * kSolarConstant / (s.earth_sun_distance_au * s.earth_sun_distance_au);
    }
    d.t_seconds.push_back(t);
    d.sun_enu.push_back(up > 0 ? dir.normalized() : Vec3{0, 0, -1});
    d.irradiance_w_m2.push_back(irradiance / kSub);
    for (int n = 1; n <= harmonics; ++n) {
      d.basis.push_back(2.0 / samples * std::polar(1.0, -n * w * t));
    }
  }
  return d;
}

void forcing_from_insolation(const DaySamples& day, const double* insolation_w_m2,
                             DiurnalForcing& f) {
  const std::size_t n = day.t_seconds.size();
  const auto h = static_cast<std::size_t>(day.harmonics);
  f.harmonics_w_m2.resize(h);
  std::fill(f.harmonics_w_m2.begin(), f.harmonics_w_m2.end(), std::complex<double>{});
  double mean = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const double i = insolation_w_m2[k];
    if (i == 0.0) continue;
    mean += i;
    for (std::size_t m = 0; m < h; ++m) f.harmonics_w_m2[m] += i * day.basis[k * h + m];
  }
  f.mean_w_m2 = mean / static_cast<double>(n);
}

}  // namespace ris
