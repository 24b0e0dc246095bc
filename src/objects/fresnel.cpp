#include "ris/objects/fresnel.h"

#include <algorithm>
#include <cmath>

namespace ris {

FresnelPair fresnel_reflection(std::complex<double> eps, double cos_theta) {
  const double c = std::clamp(cos_theta, 0.0, 1.0);
  const double sin2 = 1.0 - c * c;
  // The principal root: its imaginary part has the sign of eps'' (<= 0 for a
  // lossy medium with e^{+jwt}), a wave decaying into the medium.
  const std::complex<double> root = std::sqrt(eps - sin2);
  const FresnelPair r{(c - root) / (c + root), (eps * c - root) / (eps * c + root)};
  return r;
}

double ament_amplitude_factor(double k, double rms_height_m, double cos_theta) {
  const double g = k * rms_height_m * cos_theta;
  return std::exp(-2.0 * g * g);
}

}  // namespace ris
