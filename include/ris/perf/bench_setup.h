// Inputs for performance measurement: a seeded fractal scene of any size and
// a SLAR whose swath covers it, so `ris bench` and the Google Benchmark
// kernels (bench/) time the pipeline on terrain with relief, slopes, shadow
// and layover rather than on a flat plate.
//
// The scene is fractal value noise (sum of octaves of bilinearly
// interpolated lattice noise, amplitude halving per octave: a 1/f^2-like
// spectrum, after Musgrave's fBm in Ebert et al., "Texturing and Modeling",
// 3rd ed., ch. 16), keyed by a counter-based hash of (seed, octave, lattice
// point), so the same seed gives the same scene at any thread count.
// Categories 1..10 (the standard crop library) follow elevation bands broken
// up by a second noise field.
//
// Example:
//   ris::Scene s = ris::make_bench_scene(2000, 2000, 6.096, 7);
//   ris::RadarParams r = ris::bench_radar(ris::load_radar(path), s, 0.0);
#pragma once

#include <cstdint>

#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"

namespace ris {

// A rows x cols fractal scene of square cells, all valid, relief about
// 0.05 x the scene's smaller side (peak to trough).
Scene make_bench_scene(int rows, int cols, double cell_m, std::uint64_t seed);

// `radar` with its track (heading clockwise from north, near edge 0.5 x
// altitude ... as the radar gives it) and its swath (near range, range bins)
// set so every cell of `scene` falls inside the swath; the range bin, beam,
// film and switches are the radar's own.
RadarParams bench_radar(RadarParams radar, const Scene& scene, double heading_rad);

}  // namespace ris
