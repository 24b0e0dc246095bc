// A radar file for a command that images one channel (`ris study`, `ris
// sensitivity`, `ris greytone`): load_radar, and a file listing several
// [[channel]] tables (docs/radar-format.md, "Channels") is refused naming
// the key `channel` and the command, rather than taken as its first channel
// without a word.
//
// Example:
//   const ris::RadarParams r = ris::load_one_channel_radar(path, "ris study");
#pragma once

#include <string>

#include "ris/sensor/radar_params.h"

namespace ris {

// command: how the user called it ("ris study").
RadarParams load_one_channel_radar(const std::string& path, const std::string& command);

}  // namespace ris
