// Fresnel reflection of a plane wave at a smooth half-space of complex
// relative permittivity eps (eps' - j eps'', time factor e^{+j w t}), and the
// Ament (1953) roughness factor of the coherent (specular) reflection.
//
// Convention (docs/objects.md): the s (TE, "H") unit vector is
// e_s = k_i x n / |k_i x n|, the p (TM, "V") vectors are e_p = e_s x k for the
// incident and for the reflected direction. In that basis a perfect
// conductor is (r_s, r_p) = (-1, +1), and
//   r_s = (cos t - sqrt(eps - sin^2 t)) / (cos t + sqrt(eps - sin^2 t))
//   r_p = (eps cos t - sqrt(eps - sin^2 t)) / (eps cos t + sqrt(eps - sin^2 t))
// (Born & Wolf, Principles of Optics, 1.5.2; Balanis, Advanced Engineering
// Electromagnetics, 5.3), so r_p = 0 at the Brewster angle atan(sqrt(eps)).
//
// Example:
//   ris::FresnelPair r = ris::fresnel_reflection({5.24, -0.3}, std::cos(0.4));
#pragma once

#include <complex>

namespace ris {

struct FresnelPair {
  std::complex<double> s;  // TE (H): E perpendicular to the plane of incidence
  std::complex<double> p;  // TM (V): E in the plane of incidence
};

// cos_theta: cosine of the angle between the incoming ray and the normal, in [0, 1].
FresnelPair fresnel_reflection(std::complex<double> eps, double cos_theta);

// The perfect conductor's pair in this convention: (-1, +1).
constexpr FresnelPair pec_reflection() {
  return {{-1.0, 0.0}, {1.0, 0.0}};
}

// The AMPLITUDE factor of the coherent reflection from a surface of rms height
// h (m): exp(-2 (k h cos t)^2), so the specular POWER falls by
// exp(-4 (k h cos t)^2) = exp(-(4 pi h cos t / lambda)^2) (Ament 1953;
// Beckmann & Spizzichino 1963, eq. 5.3). k = 2 pi / lambda.
double ament_amplitude_factor(double k, double rms_height_m, double cos_theta);

}  // namespace ris
