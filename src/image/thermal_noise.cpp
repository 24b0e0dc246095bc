#include "ris/image/thermal_noise.h"

#include <algorithm>
#include <cmath>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

std::vector<double> thermal_noise_power_w(const SlarImagingParams& p, double nesz,
                                          double altitude_m, double azimuth_cell_m,
                                          double range_cell_m) {
  std::vector<double> out(static_cast<std::size_t>(p.range.count));
  const double k_radar =
      p.transmit_power_w * p.wavelength_m * p.wavelength_m / std::pow(4.0 * kPi, 3.0);
  for (int b = 0; b < p.range.count; ++b) {
    const double R = p.range.centre_m(b);
    const double cos_theta = std::clamp(altitude_m / R, 0.0, 1.0);
    // Below the altitude there is no ground: the cell is taken at grazing
    // sin(theta) >= 1e-3 so the noise stays finite.
    const double sin_theta = std::max(std::sqrt(1.0 - cos_theta * cos_theta), 1e-3);
    const double beta = std::acos(cos_theta);
    const double g = (p.elevation_gain ? p.elevation_gain(beta) : 1.0) * p.peak_gain;
    const double area = azimuth_cell_m * range_cell_m / sin_theta;
    out[static_cast<std::size_t>(b)] = k_radar * g * g * nesz * area / std::pow(R, 4);
  }
  return out;
}

void add_noise_power(SlarImage& img, const std::vector<double>& noise_power_w) {
  RIS_CHECK(noise_power_w.size() == static_cast<std::size_t>(img.bins));
#pragma omp parallel for schedule(static)
  for (int line = 0; line < img.lines; ++line) {
    for (int b = 0; b < img.bins; ++b) {
      float& v = img.mean_power_w[img.index(line, b)];
      v = static_cast<float>(double(v) + noise_power_w[static_cast<std::size_t>(b)]);
    }
  }
}

}  // namespace ris
