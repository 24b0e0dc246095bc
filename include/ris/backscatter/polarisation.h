// The band a backscatter model is evaluated for: the radar's frequency and
// polarisation (ris/sensor/polarisation.h).
#pragma once

#include "ris/sensor/polarisation.h"

namespace ris {

// What a sigma0 model needs to know about the radar.
struct RadarBand {
  double frequency_hz = 0.0;
  Polarisation polarisation = Polarisation::HH;
};

}  // namespace ris
