// Changing a radar description from the page: its TOML keys overridden, the
// near-range depression angle turned into the keys that set it, and the test
// that decides whether a change touches only the film (so that the server
// re-renders from the kept mean power instead of simulating again).
//
// Example:
//   toml::table doc = radar_doc;
//   ris::set_near_range_depression(doc, radar, ris::deg_to_rad(25.0));
//   ris::RadarParams next = ris::radar_from_toml(doc, radar.source_file);
#pragma once

#include <toml++/toml.h>

#include "ris/sensor/radar_params.h"

namespace ris {

// Sets the near slant range and, for a track given by heading and near-edge
// distance, the ground distance to the scene's near edge so that the near
// range is seen at depression angle `depression_rad` over a flat datum at
// the radar's altitude H:
//   R_near = H / sin(depression),  near edge = H / tan(depression)
// (the seed's RADAR(6) sweep delay and GROUND(1) for that angle, TR 319
// Appendix A). sweep_delay is replaced by near_range; a far_range given keeps
// its distance from the near range. `radar`: doc parsed (for H). Throws
// InputError (source "request body", key "depression") for an angle outside
// (0, 90) degrees.
void set_near_range_depression(toml::table& radar_doc, const RadarParams& radar,
                               double depression_rad);

// Sets the slant-range swath (far range minus near range) to `swath_m`:
// sweep_length, range_bins and far_range are replaced by far_range =
// R_near + swath. Throws InputError (key "swath") unless swath_m > 0.
void set_slant_swath(toml::table& radar_doc, const RadarParams& radar, double swath_m);

// Whether going from `before` to `after` (the descriptions and what they
// parse to) changes only what the image chain after the mean power uses:
// the [film] table's density range, gamma, k, m, fading law and the fading
// switch. Any other key, or another greytone switch, changes the mean power.
bool film_only_change(const toml::table& before_doc, const toml::table& after_doc,
                      const RadarParams& before, const RadarParams& after);

}  // namespace ris
