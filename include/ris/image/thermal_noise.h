// Thermal noise of a SAR as a noise-equivalent sigma0 (NESZ): the receiver
// noise in a pixel equals the mean power of flat ground at the datum whose
// sigma0 is NESZ (the usual SAR specification, e.g. Curlander and McDonough,
// "Synthetic Aperture Radar", 1991, section 2.7), so
//
//   P_n(R) = P_t G^2(beta) lambda^2 NESZ A(R) / ((4 pi)^3 R^4),
//   A(R) = rho_az rho_r / sin(theta),  cos(theta) = H / R,
//
// with the same antenna gain and resolution cell as the image (multilooked
// resolutions). Noise adds to the mean power, so shadows and dark water hold
// noise rather than zeros; fading (or the coherent sum) then acts on the sum,
// as for a real receiver.
//
// Example:
//   std::vector<double> pn = ris::thermal_noise_power_w(imaging, nesz, H, az_m, rg_m);
//   ris::add_noise_power(image, pn);
#pragma once

#include <vector>

#include "ris/image/slar_image.h"

namespace ris {

// Per range bin of p.range.
std::vector<double> thermal_noise_power_w(const SlarImagingParams& p, double nesz,
                                          double altitude_m, double azimuth_cell_m,
                                          double range_cell_m);

// Adds noise_power_w[bin] to every pixel of the image's mean power.
void add_noise_power(SlarImage& image, const std::vector<double>& noise_power_w);

}  // namespace ris
