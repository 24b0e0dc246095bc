#include "ris/sensor/radar_params.h"

#include <fmt/format.h>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

double RadarParams::wavelength_m() const {
  return kSpeedOfLight_m_per_s / frequency_hz;
}

RadarParams radar_at_band(const RadarParams& radar, double frequency_hz,
                          Polarisation polarisation) {
  if (!(frequency_hz > 0.0)) {
    throw InputError(radar.source_file, "frequency",
                     fmt::format("expected a frequency above 0 Hz, got {}", frequency_hz));
  }
  RadarParams r = radar;
  r.frequency_hz = frequency_hz;
  r.polarisation = polarisation;
  // As radar_from_toml derives them (ris/sensor/radar_config.cpp).
  if (!r.reference.wavelength_given) r.reference.wavelength_m = r.wavelength_m();
  if (r.beamwidth_antenna_length_m > 0.0) {
    r.azimuth_beamwidth_rad = r.wavelength_m() / r.beamwidth_antenna_length_m;
    if (r.azimuth_beamwidth_rad >= kPi) {
      throw InputError(radar.source_file, "azimuth_beamwidth",
                       fmt::format("expected a beamwidth below 180 deg; lambda / L at {:g} GHz "
                                   "gives {:.1f} deg",
                                   frequency_hz / 1e9, rad_to_deg(r.azimuth_beamwidth_rad)));
    }
  }
  return r;
}

}  // namespace ris
