// The radar of the streamed-run tests (slar_stream_test.cpp,
// slar_stream_targets_test.cpp): the seed's Figure 4-5 radar on a track of
// any heading over a test scene, low enough (600 m) for shadow behind the
// relief and the tower, left-looking on the east-west tracks (their lines
// are columns, cells counted the other way across).
#pragma once

#include <string>

#include "build_paths.h"
#include "ris/perf/bench_setup.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/units.h"

namespace ris::test {

inline RadarParams stream_test_radar(const Scene& s, double heading_deg) {
  RadarParams r = load_radar(std::string(data_dir()) + "/radars/seed-fig4-5.toml");
  r = bench_radar(r, s, deg_to_rad(heading_deg));
  r.track.altitude_m = 600.0;
  r.track.near_edge_ground_m = 1500.0;
  if (heading_deg == 90.0 || heading_deg == 270.0) r.track.look_side = LookSide::left;
  return bench_radar(r, s, deg_to_rad(heading_deg));
}

}  // namespace ris::test
