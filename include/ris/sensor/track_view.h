// Whether a resolved track can see its scene at all (issue 38: a radar
// looking away from the scene blamed `sweep_delay` and printed a slant range
// "inf to -inf"). Checked before the run, from the scene's corners only, so
// that the message names the key that is wrong:
//  - every corner on the side the radar does not look (u <= 0, with u the
//    ground distance along the look direction g of ris/sensor/track.h):
//    `track.look_side` (or the track's start and end, swapped);
//  - every corner behind the track's start or past its end (s < 0 or
//    s > length): the track's start and end.
// A scene on the looked side but outside the swath passes: that one is the
// sweep delay's and length's (check_swath_hits_scene, ris/sim/slar_line_blocks.h).
//
// Example:
//   const ris::Track t = ris::resolve_track(radar.track, scene, radar.source_file);
//   ris::check_scene_in_view(radar.track, t, scene, radar.source_file);
#pragma once

#include <string>

#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"
#include "ris/sensor/track.h"

namespace ris {

// The scene's extent in the track's (s, u) frame, from its four corners.
struct TrackSceneExtent {
  double s_min_m, s_max_m;  // along track, from the track's start
  double u_min_m, u_max_m;  // across, positive on the looked side
};
TrackSceneExtent track_scene_extent(const Track& track, const Scene& grid);

// Throws InputError (file: the radar's) naming `track.look_side` or the
// track's end points when no part of the scene can be seen (see above).
void check_scene_in_view(const TrackSpec& spec, const Track& track, const Scene& grid,
                         const std::string& file);

}  // namespace ris
