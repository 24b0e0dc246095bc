// A camera's detector: radiance to electrons to a digital number (issue 35
// item 2; docs/sensors.md "Detector"). The photon transfer model (Janesick,
// Photon Transfer, SPIE PM170, 2007, chapters 2-4): a pixel collects
//   N = electrons_per_radiance x L
// signal electrons, with shot noise (Poisson in N) and read noise
// (Gaussian, read_noise_e electrons rms); the count is clipped at the full
// well and quantised to `bits`: DN = round(N' (2^bits - 1) / full_well_e).
// electrons_per_radiance lumps the aperture, the pixel's solid angle, the
// band width, the quantum efficiency and the integration time into one key.
#pragma once

#include <cstdint>

#include "ris/util/counter_rng.h"

namespace ris {

struct Detector {
  double electrons_per_radiance = 0;  // e- per W m^-2 sr^-1 um^-1
  double read_noise_e = 0;
  double full_well_e = 0;
  int bits = 12;
};

// Poisson variate of mean `mean` (exact by Knuth's product of uniforms below
// 30, else the normal approximation with continuity correction, whose error
// in the variance is below 1/(12 mean)).
double poisson_electrons(double mean, CounterRng& rng);

// The digital number of radiance L (shot and read noise drawn from rng).
std::uint16_t digital_number(const Detector& d, double radiance, CounterRng& rng);

}  // namespace ris
