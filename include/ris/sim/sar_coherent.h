// The coherent SAR option (radar [sar] coherent = true; MODEL.md section 3,
// "azimuth, SAR"): speckle from the physics instead of a fading law.
//
// Every visible ground element i (one per geometry sample) is a scatterer
// with complex reflectivity a_i exp(j phi_i), phi_i uniform in [0, 2 pi) and
// a_i Rayleigh with E a_i^2 = P_i, its mean power from the radar equation
// (the same number the incoherent image sums): a circular Gaussian, drawn
// from CounterRng keyed by (seed, sample, line, look) so the picture never
// depends on thread count. Why Rayleigh and not a fixed amplitude: a ground
// cell is many wavelengths across and holds many unresolved scatterers, and
// with a fixed amplitude a resolution cell of N_eff elements would give
// ENL = 1 / (1 - 1 / N_eff) (1.03 for N_eff = 37, measured), not 1. It lies at its zero-Doppler
// position: along-track s of its line, slant range R_i, and carries the
// two-way phase -4 pi R_i / lambda. Point targets (ris/sim/point_target.h)
// are scatterers with phase 0 (a corner reflector's response does not
// fluctuate) at their exact s and R. A pixel (line k, bin b) sums
//
//   z(k, b) = sum_i a_i exp(j (phi_i - 4 pi R_i / lambda)) h_r(R_i - R_b) h_a(s_i - s_k)
//
// with the compressed impulse responses h(x) = A sinc(0.886 x / rho), whose
// 3 dB width (of |h|^2) is the resolution rho (c / (2B) in range, L / 2 in
// azimuth): sinc(x) = sin(pi x) / (pi x), 0.886 = the half-power width of
// sinc^2 in units of its null spacing (Curlander and McDonough 1991, section
// 3.2). A = sqrt(0.886 / T) with T the fraction of sinc^2's energy inside the
// truncation, so that E|z|^2 equals the incoherent box image (the mean power)
// for any distribution of ground samples denser than the resolution.
// Truncation: h is cut at 8 null spacings each side of the peak (the main
// lobe and 7 sidelobes; 98.7% of sinc^2's energy), so the sidelobes an IRF
// measurement sees are those of an unweighted sinc: PSLR -13.26 dB, ISLR
// -10.3 dB for the truncated response (-9.7 dB untruncated).
//
// Separable: the sum runs as range compression per geometry line (each
// element into the bins within 8 null spacings of R_i; the sinc from a table)
// then azimuth compression along each bin (a fixed kernel over lines, since
// the lines are equally spaced). Thermal noise (NESZ, sim.noise_power_w) is a
// circular complex Gaussian added per pixel.
//
// Multilook (L_r x L_a looks): each look is an independent realisation of the
// ground's phases at the look's resolution L_r rho_r x L_a rho_a (sub-band
// processing), and the intensities are averaged: ENL L_r L_a on uniform
// ground, a point target at the looks' resolution.
//
// Cost: per look, samples x (18 rho_r' / dr) + lines x bins x (18 rho_a' /
// ds) complex multiply-adds; no allocation inside the loops.
//
// Example:
//   ris::SlarSimulation sim = ris::simulate_slar(scene, radar, *sigma0, options);
//   std::vector<float> intensity = ris::coherent_sar_intensity(sim, 42);
//   ris::SlarPictures pic = ris::render_slar(sim, 42, intensity);
#pragma once

#include <cstdint>
#include <vector>

#include "ris/sim/slar_simulation.h"

namespace ris {

inline constexpr double kSincHalfPowerWidth = 0.88589;  // of sinc^2, in null spacings
inline constexpr int kSincSupportNulls = 8;             // truncation, each side

// The image's intensity (W), lines x bins like sim.image; no-data pixels are
// NaN. Needs sim.image.element_power_w (simulate_slar keeps it for a
// coherent SAR).
std::vector<float> coherent_sar_intensity(const SlarSimulation& sim, std::uint64_t seed);

}  // namespace ris
