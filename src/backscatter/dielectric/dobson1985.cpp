// Dobson 1985: semi-empirical dielectric mixing model of moist soil.
//
//   eps'  = [1 + (rho_b/rho_s)(eps_s^a - 1) + mv^b' eps_fw'^a - mv]^(1/a)
//   eps'' = [mv^b'' eps_fw''^a]^(1/a)
//   a = 0.65, rho_s = 2.66 g/cm3, eps_s = (1.01 + 0.44 rho_s)^2 - 0.062
//   b'  = 1.2748 - 0.519 S - 0.152 C,   b'' = 1.33797 - 0.603 S - 0.166 C
// with the free-water Debye permittivity
//   eps_fw'  = eps_w_inf + (eps_w0 - eps_w_inf) / (1 + (2 pi f tau_w)^2)
//   eps_fw'' = 2 pi f tau_w (eps_w0 - eps_w_inf) / (1 + (2 pi f tau_w)^2)
//              + sigma_eff / (2 pi eps_0 f) (rho_s - rho_b) / (rho_s mv)
//   sigma_eff = -1.645 + 1.939 rho_b - 2.25622 S + 1.594 C   (S/m; default,
//               "dobson1985": Dobson et al. 1985, fitted at 1.4-18 GHz)
//   sigma_eff = 0.0467 + 0.2204 rho_b - 0.4111 S + 0.6614 C  ("peplinski1995":
//               Peplinski, Ulaby & Dobson 1995 eq. 10, fitted at 0.3-1.3 GHz;
//               its companion correction of eps' below 1.4 GHz, 1.15 eps' -
//               0.68, is not applied: ris's range starts at 1.4 GHz)
// and eps_w_inf = 4.9, eps_w0(T) and tau_w(T) of Stogryn (1971) as given in
// Ulaby, Moore & Fung (1986), Microwave Remote Sensing vol. III, appendix E.
// Source: Dobson, M. C., Ulaby, F. T., Hallikainen, M. T. & El-Rayes, M. A.
// (1985), "Microwave dielectric behavior of wet soil - Part II: Dielectric
// mixing models", IEEE Trans. Geosci. Remote Sens. GE-23(1), 35-46, eqs. (22),
// (23), (28); sigma_eff as restated by Peplinski, Ulaby & Dobson (1995), IEEE
// TGRS 33(3), 803-807.
// Inputs: mv (m3/m3), S and C (mass fractions), rho_b (g/cm3), T (deg C).
// Validity: 1.4-18 GHz, 0 <= mv <= 0.5 (the measurements it was fitted to).
#include <cmath>

#include "ris/backscatter/dielectric.h"
#include "ris/util/units.h"

namespace ris {

std::complex<double> dobson1985_permittivity(const SoilComposition& soil, double frequency_hz) {
  constexpr double kAlpha = 0.65;
  constexpr double kRhoS = 2.66;             // specific density of soil solids, g/cm3
  constexpr double kEps0 = 8.854187817e-12;  // F/m
  constexpr double kEpsWInf = 4.9;
  const double t = soil.temperature_c;
  const double s = soil.sand_fraction;
  const double c = soil.clay_fraction;
  const double rho_b = soil.bulk_density_g_cm3;
  const double mv = soil.moisture_m3_m3;

  const double eps_s = std::pow(1.01 + 0.44 * kRhoS, 2.0) - 0.062;
  const double beta_re = 1.2748 - 0.519 * s - 0.152 * c;
  const double beta_im = 1.33797 - 0.603 * s - 0.166 * c;
  const double sigma_eff = soil.conductivity == DobsonConductivity::dobson1985
                               ? -1.645 + 1.939 * rho_b - 2.25622 * s + 1.594 * c
                               : 0.0467 + 0.2204 * rho_b - 0.4111 * s + 0.6614 * c;

  // Free water (Stogryn 1971): static permittivity and 2 pi times relaxation time.
  const double eps_w0 = 88.045 - 0.4147 * t + 6.295e-4 * t * t + 1.075e-5 * t * t * t;
  const double two_pi_tau = 1.1109e-10 - 3.824e-12 * t + 6.938e-14 * t * t - 5.096e-16 * t * t * t;
  const double ft = frequency_hz * two_pi_tau;
  const double eps_fw_re = kEpsWInf + (eps_w0 - kEpsWInf) / (1.0 + ft * ft);
  double eps_fw_im = ft * (eps_w0 - kEpsWInf) / (1.0 + ft * ft);
  if (mv > 0.0) {
    eps_fw_im += sigma_eff / (2.0 * kPi * kEps0 * frequency_hz) * (kRhoS - rho_b) / (kRhoS * mv);
  }

  const double re = std::pow(1.0 + (rho_b / kRhoS) * (std::pow(eps_s, kAlpha) - 1.0) +
                                 std::pow(mv, beta_re) * std::pow(eps_fw_re, kAlpha) - mv,
                             1.0 / kAlpha);
  const double im =
      mv > 0.0 ? std::pow(std::pow(mv, beta_im) * std::pow(eps_fw_im, kAlpha), 1.0 / kAlpha) : 0.0;
  return {re, -im};
}

}  // namespace ris
