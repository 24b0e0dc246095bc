#include "ris/sensors_eo/detector.h"

#include <algorithm>
#include <cmath>

namespace ris {

double poisson_electrons(double mean, CounterRng& rng) {
  if (mean <= 0) return 0.0;
  if (mean < 30.0) {
    // Knuth, The Art of Computer Programming vol. 2, 3.4.1: multiply
    // uniforms until the product falls below exp(-mean).
    const double limit = std::exp(-mean);
    double product = rng.uniform();
    int k = 0;
    while (product > limit) {
      ++k;
      product *= rng.uniform();
    }
    return k;
  }
  return std::max(0.0, std::floor(mean + std::sqrt(mean) * rng.normal() + 0.5));
}

std::uint16_t digital_number(const Detector& d, double radiance, CounterRng& rng) {
  const double signal = poisson_electrons(std::max(0.0, d.electrons_per_radiance * radiance), rng);
  const double electrons = std::clamp(signal + d.read_noise_e * rng.normal(), 0.0, d.full_well_e);
  const double levels = std::ldexp(1.0, d.bits) - 1.0;
  return static_cast<std::uint16_t>(std::lround(electrons * levels / d.full_well_e));
}

}  // namespace ris
