// Mironov 2009: generalized refractive mixing dielectric model (GRMDM) of
// moist soil, with spectroscopic parameters regressed on clay content.
//
//   n_m = n_d + (n_b - 1) mv                               mv <= mv_t
//       = n_d + (n_b - 1) mv_t + (n_u - 1)(mv - mv_t)      mv >  mv_t
//   k_m = k_d + k_b mv   (resp. k_d + k_b mv_t + k_u (mv - mv_t))
//   eps' = n_m^2 - k_m^2,   eps'' = 2 n_m k_m
// where n and k of bound (b) and free (u) water come from Debye spectra
//   eps_p = eps_inf + (eps_0p - eps_inf)/(1 - j 2 pi f tau_p) + j sigma_p/(2 pi eps_0 f)
// and, with C the clay content in percent (eqs. 17-25 of the paper):
//   n_d = 1.634 - 0.539e-2 C + 0.2748e-4 C^2,  k_d = 0.03952 - 0.04038e-2 C
//   mv_t = 0.02863 + 0.30673e-2 C
//   eps_0b = 79.8 - 85.4e-2 C + 32.7e-4 C^2,  tau_b = 1.062e-11 + 3.450e-12 e-2 C
//   sigma_b = 0.3112 + 0.467e-2 C,  sigma_u = 0.3631 + 1.217e-2 C
//   eps_0u = 100, tau_u = 8.5e-12 s, eps_inf = 4.9
// Source: Mironov, V. L., Kosolapova, L. G. & Fomin, S. V. (2009),
// "Physically and mineralogically based spectroscopic dielectric model for
// moist soils", IEEE Trans. Geosci. Remote Sens. 47(7), 2059-2070.
// Inputs: mv (m3/m3), clay (mass fraction). Sand is not used.
// Validity: 0.045-26.5 GHz, 0-76 % clay, room temperature (about 20 C).
#include <cmath>

#include "ris/backscatter/dielectric.h"
#include "ris/util/units.h"

namespace ris {

namespace {

struct RefractiveIndex {
  double n;
  double k;
};

// Refractive index n - j k of a Debye medium with conductivity.
RefractiveIndex debye_index(double eps_static, double tau_s, double sigma_s_m, double f_hz) {
  constexpr double kEps0 = 8.854187817e-12;
  constexpr double kEpsInf = 4.9;
  const double wt = 2.0 * kPi * f_hz * tau_s;
  const double re = kEpsInf + (eps_static - kEpsInf) / (1.0 + wt * wt);
  const double im =
      (eps_static - kEpsInf) * wt / (1.0 + wt * wt) + sigma_s_m / (2.0 * kPi * kEps0 * f_hz);
  const double mag = std::hypot(re, im);
  return {std::sqrt((mag + re) / 2.0), std::sqrt((mag - re) / 2.0)};
}

}  // namespace

std::complex<double> mironov2009_permittivity(const SoilComposition& soil, double frequency_hz) {
  const double c = soil.clay_fraction * 100.0;  // percent
  const double mv = soil.moisture_m3_m3;
  const double nd = 1.634 - 0.539e-2 * c + 0.2748e-4 * c * c;
  const double kd = 0.03952 - 0.04038e-2 * c;
  const double mvt = 0.02863 + 0.30673e-2 * c;
  const double eps0b = 79.8 - 85.4e-2 * c + 32.7e-4 * c * c;
  const double taub = 1.062e-11 + 3.450e-12 * 1e-2 * c;
  const double sigmab = 0.3112 + 0.467e-2 * c;
  const double sigmau = 0.3631 + 1.217e-2 * c;
  const RefractiveIndex b = debye_index(eps0b, taub, sigmab, frequency_hz);
  const RefractiveIndex u = debye_index(100.0, 8.5e-12, sigmau, frequency_hz);

  double nm = 0.0;
  double km = 0.0;
  if (mv <= mvt) {
    nm = nd + (b.n - 1.0) * mv;
    km = kd + b.k * mv;
  } else {
    nm = nd + (b.n - 1.0) * mvt + (u.n - 1.0) * (mv - mvt);
    km = kd + b.k * mvt + u.k * (mv - mvt);
  }
  return {nm * nm - km * km, -2.0 * nm * km};
}

}  // namespace ris
