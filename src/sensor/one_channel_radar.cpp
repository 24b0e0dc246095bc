#include "ris/sensor/one_channel_radar.h"

#include <fmt/format.h>

#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"

namespace ris {

RadarParams load_one_channel_radar(const std::string& path, const std::string& command) {
  RadarParams r = load_radar(path);
  if (r.channels.size() > 1) {
    std::string names;
    for (const RadarChannel& c : r.channels) names += (names.empty() ? "" : ", ") + c.name;
    throw InputError(path, "channel",
                     fmt::format("{} images one channel; this file lists {} [[channel]] tables "
                                 "({}): give a radar file with one channel (copy that channel's "
                                 "keys to the top level of a file of its own), or run ris "
                                 "simulate, which images every channel",
                                 command, r.channels.size(), names));
  }
  return r;
}

}  // namespace ris
