#include "ris/sensor/radar_params.h"

#include "ris/util/units.h"

namespace ris {

double RadarParams::wavelength_m() const {
  return kSpeedOfLight_m_per_s / frequency_hz;
}

}  // namespace ris
