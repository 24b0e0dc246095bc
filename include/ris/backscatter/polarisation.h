// Radar polarisation (transmit, receive) and the band a backscatter model is
// evaluated for.
#pragma once

#include <string>
#include <string_view>

namespace ris {

enum class Polarisation { HH, VV, HV, VH };

// "HH", "hh", "VV", ... -> Polarisation; throws std::invalid_argument naming
// the accepted values.
Polarisation parse_polarisation(std::string_view text);
std::string_view to_string(Polarisation p);

// What a sigma0 model needs to know about the radar.
struct RadarBand {
  double frequency_hz = 0.0;
  Polarisation polarisation = Polarisation::HH;
};

}  // namespace ris
