#include "ris/sensors_eo/lambertian.h"

#include <algorithm>
#include <numbers>

namespace ris {

double lambertian_radiance(double reflectance, const Illumination& e) {
  const double direct =
      e.lit ? e.sun_irradiance_w_m2_um * std::max(e.cos_incidence, 0.0) * e.transmittance_down
            : 0.0;
  return reflectance * (direct + e.sky_irradiance_w_m2_um) / std::numbers::pi * e.transmittance_up +
         e.path_radiance_w_m2_sr_um;
}

double thermal_leaving_radiance(double emissivity, double blackbody_band_radiance,
                                double sky_band_radiance) {
  return emissivity * blackbody_band_radiance + (1.0 - emissivity) * sky_band_radiance;
}

}  // namespace ris
