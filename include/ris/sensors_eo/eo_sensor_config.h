// An optical or thermal sensor file (TOML), e.g. data/sensors_eo/optical.toml:
//   kind = "optical"            # or "thermal"
//   date = "2024-06-21"         # UTC
//   time = "10:30:00"           # UTC
//   bands = ["blue", "green", "red", "nir"]   # or ["lwir", "mwir"]
//   noise = 0.0                 # Gaussian sigma per band: radiance units
//                               # (optical) or kelvin (thermal)
//   seed = 1
//   latitude = 48.1             # optional: else from the scene's CRS centre
//   longitude = 11.6
//   [atmosphere]
//   transmittance = 0.8         # one-way, each direction
//   sky_fraction = 0.1          # E_sky = sky_fraction x E_sun cos(theta_z) T
//   path_radiance = 0.0         # W m^-2 sr^-1 um^-1
//   sky_temperature = 0.0       # K, downwelling thermal sky as a blackbody
//   [thermal]
//   mean_temperature = 288.0    # K, daily mean surface temperature
// docs/sensors.md, "Sensor file".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ris/sensors_eo/eo_band.h"
#include "ris/sensors_eo/sun_position.h"

namespace ris {

enum class EoKind { optical, thermal };

struct EoSensorConfig {
  std::string path;
  EoKind kind = EoKind::optical;
  UtcDateTime when;
  std::vector<EoBand> bands;
  double noise = 0;
  std::uint64_t seed = 1;
  std::optional<double> latitude_deg;
  std::optional<double> longitude_deg;
  double transmittance = 0.8;
  double sky_fraction = 0.1;
  double path_radiance = 0.0;
  double sky_temperature_k = 0.0;
  double mean_temperature_k = 288.0;
};

// Throws InputError naming the file and key: unknown kind or band, an
// optical band for a thermal sensor (or the reverse), a bad date or time,
// transmittance or sky_fraction outside [0, 1], negative noise, unknown keys.
EoSensorConfig parse_eo_sensor(const std::string& text, const std::string& path);
EoSensorConfig load_eo_sensor(const std::string& path);

}  // namespace ris
