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
//   [camera]                    # optional: a frame camera (frame_camera.h)
//   position = [500, 200]       # scene metres (the scene's CRS)
//   altitude = "1500 m"         # above the scene's height datum
//   heading = "0 deg"           # clockwise from north
//   depression = "45 deg"       # below the horizontal; 90 deg: nadir
//   fov = "30 deg"              # horizontal field of view
//   columns = 640
//   rows = 480
//   samples = 2                 # rays per pixel along each axis
//   mtf_at_nyquist = 0.3        # Gaussian MTF; 1: none
//   [detector]                  # optional, optical cameras: digital numbers
//   electrons_per_radiance = 200   # e- per W m^-2 sr^-1 um^-1
//   read_noise = 10             # e- rms
//   full_well = 20000           # e-
//   bits = 12
// docs/sensors.md, "Sensor file".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ris/sensors_eo/detector.h"
#include "ris/sensors_eo/eo_band.h"
#include "ris/sensors_eo/frame_camera.h"
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
  std::optional<FrameCamera> camera;
  std::optional<Detector> detector;
};

// Throws InputError naming the file and key: unknown kind or band, an
// optical band for a thermal sensor (or the reverse), a bad date or time,
// transmittance or sky_fraction outside [0, 1], negative noise, unknown keys,
// a band named twice, a camera of more than kMaxCameraRays rays (or out of
// its bounds), a detector on a thermal sensor.
EoSensorConfig parse_eo_sensor(const std::string& text, const std::string& path);
EoSensorConfig load_eo_sensor(const std::string& path);

}  // namespace ris
