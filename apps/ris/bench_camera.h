// `ris bench` (the default bench): the frame camera's ray rate (issue 35's
// goal: 20 M camera rays per second on 2 threads, primary ray and a shadow
// ray per pixel).
#pragma once

#include <string>

namespace ris::app {

// The shipped town through data/sensors_eo/optical-camera-town.toml at one
// sample per pixel: the scene grid's sun rays (one shadow ray per cell) and
// the camera's primary rays, each timed on 2 threads (median of `repeats`),
// and the rate of both together per camera pixel.
void run_camera_bench(const std::string& data_dir, int repeats);

}  // namespace ris::app
