// Radar polarisation (transmit, receive): a property of the radar
// (ris/sensor/radar_params.h) that the backscatter models read
// (ris/backscatter/polarisation.h).
#pragma once

#include <string>
#include <string_view>

namespace ris {

enum class Polarisation { HH, VV, HV, VH };

// "HH", "hh", "VV", ... -> Polarisation; throws std::invalid_argument naming
// the accepted values.
Polarisation parse_polarisation(std::string_view text);
std::string_view to_string(Polarisation p);

}  // namespace ris
