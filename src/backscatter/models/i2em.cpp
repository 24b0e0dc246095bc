// Improved integral equation model (I2EM): backscatter of a single-scale
// randomly rough dielectric surface, HH and VV by single scattering, HV by
// the IEM's multiple-scattering term.
//
// Co-polarised (backscatter case of the bistatic I2EM, theta_s = theta,
// phi_s = pi), with k the wavenumber, s the rms height, c = cos theta:
//
//   sigma_pp = S(theta) k^2/2 exp(-2 (k s c)^2)
//              sum_{n>=1} |s^n I_pp^n|^2 W^(n)(2 k sin theta) / n!
//   s^n I_pp^n = exp(-(k s c)^2) [ x^n f_pp
//                + (k s / 4) (F_pp(up,i) + F_pp(dn,s)) [n = 1]
//                + (k s / 4) (F_pp(dn,i) + F_pp(up,s)) x^(n-1) ],   x = 2 k s c
//   f_vv = 2 R_v / c,  f_hh = -2 R_h / c
//
// where R_v, R_h are the Fresnel coefficients moved towards their nadir value
// R_0 = (sqrt(eps) - 1) / (sqrt(eps) + 1) by the transition function of
// Wu, Chen, Shi & Fung (2001): R_pT = R_p + (+-R_0 - R_p) T_f with
//   T_f = 1 - (a1 / b1) |F_t + 8 R_0 / c|^2 / 4,
//   F_t = 8 R_0^2 sin theta (c + sqrt(eps - sin^2)) / (c sqrt(eps - sin^2)),
//   a1 = sum (k s c)^(2n)/n! W^(n),
//   b1 = sum (k s c)^(2n)/n! |F_t/2 + 2^(n+1) R_0/c exp(-(k s c)^2)|^2 W^(n)
// (the ratio S_t / S_t0 of the source written without its 0/0 at nadir).
// The complementary-field coefficients F_pp(up/dn, i/s) are the backscatter
// case of Fung, Liu, Chen & Tsay (2002); they are k times the dimensionless
// sums in complementary_field() below. S(theta) = 1 / (1 + 2 g(mu)) is
// Smith's (1967) bistatic shadowing with g(mu) = (exp(-mu^2)/(sqrt(pi) mu)
// - erfc(mu)) / 2, mu = cot theta / (sqrt(2) m), m the rms slope.
// The series runs to the first n >= 2 with (4 (k s c)^2)^n / n! <= 1e-8.
//
// Cross-polarised (Fung 1994 ch. 4; the form of Ulaby & Long 2014):
//   sigma_hv = S_x(theta) integral_{0.1}^{1} dr integral_0^pi dphi
//              exp(-2 (k s c)^2)/(4 pi) |F_vh(r, phi)|^2 r sha(r)
//              [sum_n (k s c)^(2n)/n! w_n(r-)] [sum_m (k s c)^(2m)/m! w_m(r+)]
// on the normalised spectral plane (r < 1: propagating waves), with
// S_x = 1 / (1 + g(mu)). Both integrals by 20-point Gauss-Legendre
// (Boost.Math; two panels in u); r = R sin u (R^2 = 1.0001) takes out the
// 1/q edge at r -> 1. An HV curve of 1801 angles (a LUT) costs about 0.5 s.
//
// Sources: Fung, Li & Chen (1992), IEEE TGRS 30(2), 356-369 (IEM);
// Fung, Liu, Chen & Tsay (2002), J. Electromagn. Waves Appl. 16(5), 689-702
// (I2EM); Fung & Chen (2004), IEEE GRSL 1(2), 75-77; Wu et al. (2001), IEEE
// TGRS 39(9), 2040-2050 (transition function); Smith (1967), IEEE TAP 15(5),
// 668-671 (shadowing). The equations as written and the cross-polarised
// integral's limits and regularisation (q = sqrt(1.0001 - r^2), r >= 0.1)
// follow Ulaby & Long (2014), Microwave Radar and Radiometric Remote Sensing,
// sec. 10-3.9, Code 10.1, so that values compare with that reference
// implementation; unlike it, no angle offset (it adds 0.01 rad to theta in
// the co-polarised part and 0.001 rad in the cross-polarised one) is applied.
// Test values: src/backscatter/models/i2em_test.cpp.
//
// Parameters:
//   rms_height          s (length)
//   correlation_length  l (length)
//   correlation         "gaussian" or "exponential"
//   permittivity        "eps' - eps''j" or a dielectric model (as spm)
// Validity: ks <= 3 enforced per band (beyond it the single-scattering
// approximation is outside its sources' tested range and the series needs
// many terms); allow_extrapolation = true lets it through with a warning.
//
// TOML:  [category.model]
//        name = "i2em"
//        rms_height = "1 cm"
//        correlation_length = "8 cm"
//        correlation = "exponential"
//        permittivity = "15 - 3j"
#include <boost/math/quadrature/gauss.hpp>

#include "backscatter/models/models.h"
#include "backscatter/models/soil_permittivity.h"

namespace ris::detail {

namespace {

using cd = std::complex<double>;

// Roughness spectrum W^(n)(K) of the n-th power of the correlation function
// (the 2-D Fourier transform over 2 pi), l the correlation length.
double roughness_spectrum(bool gaussian, double l, int n, double big_k) {
  if (gaussian) return l * l / (2.0 * n) * std::exp(-(big_k * l) * (big_k * l) / (4.0 * n));
  const double a = big_k * l / n;
  return (l / n) * (l / n) * std::pow(1.0 + a * a, -1.5);
}

// First n >= 2 with y^n / n! <= 1e-8 (y = 4 (k s c)^2), in logarithms so that
// a rough surface cannot overflow the factorial.
int series_terms(double y) {
  int n = 2;
  while (n < 1000 && n * std::log(y) - std::lgamma(n + 1.0) > std::log(1e-8)) ++n;
  return n;
}

// Smith's shadowing term g(mu), 0 when the slopes cannot shadow (mu -> inf).
double smith_g(double mu) {
  if (!(mu < 30.0)) return 0.0;
  return 0.5 * (std::exp(-mu * mu) / (std::sqrt(kPi) * mu) - std::erfc(mu));
}

// F_pp / k for one of the four complementary fields (up = +1 or -1; incident
// or scattered side), backscatter geometry. c, sn: cos and sin theta; rt =
// sqrt(eps - sin^2 theta); R the Fresnel coefficient of the polarisation.
// The c_ij are the source's coefficients over k^2 with phi = 0, phi_s = pi,
// theta_s = theta substituted.
cd complementary_field(bool vertical, int up, bool incident_side, cd eps, double c, double sn,
                       cd rt, cd r) {
  const double s2 = sn * sn;
  const double u = up;
  cd c11, c21, c31, c41, c51, c12, c22, c32, c42, c52;
  if (incident_side) {
    const double g = u * c;  // G_qi / k; q_i / k = u c as well
    const cd gt = u * rt;    // G_qti / k
    const double d = c - g;  // (k_sz - q_i) / k
    c11 = -d;
    c21 = c * (2.0 * s2 - g * d);
    c31 = -s2 * (d + 2.0 * g);
    c41 = c * (-c * d - 2.0 * s2);
    c51 = g * (c * d + 2.0 * s2);
    c12 = c11;
    c22 = c * (2.0 * s2 - gt * d);
    c32 = -s2 * (d + 2.0 * gt);
    c42 = c41;
    c52 = gt * (c * d + 2.0 * s2);
  } else {
    const double g = u * c;  // G_qs / k = q_s / k
    const cd gt = u * rt;    // G_qts / k
    const double p = c + g;  // (k_z + q_s) / k
    c11 = -p;
    c21 = -g * (c * p + 2.0 * s2);
    c31 = s2 * (g - c);
    c41 = -c * (c * p + 2.0 * s2);
    c51 = c * (2.0 * s2 + g * p);
    c12 = c11;
    c22 = -gt * (c * p + 2.0 * s2);
    c32 = c31;
    c42 = c41;
    c52 = c * (2.0 * s2 + gt * p);
  }
  const double q = c;  // q / k
  const cd qt = rt;    // q_t / k
  const cd a = 1.0 + r;
  const cd b = 1.0 - r;
  if (vertical) {
    return a * (-b * c11 / q + a * c12 / qt) + b * (b * c21 / q - a * c22 / qt) +
           a * (b * c31 / q - a * c32 / (eps * qt)) + b * (a * c41 / q - eps * b * c42 / qt) +
           a * (a * c51 / q - b * c52 / qt);
  }
  return a * (b * c11 / q - eps * a * c12 / qt) - b * (b * c21 / q - a * c22 / qt) -
         a * (b * c31 / q - a * c32 / qt) - b * (a * c41 / q - b * c42 / qt) -
         a * (a * c51 / q - b * c52 / qt);
}

double i2em_copol(cd eps, double k, double s, double l, bool gaussian, double theta,
                  bool vertical) {
  const double c = std::cos(theta);
  const double sn = std::sin(theta);
  const double ksc = k * s * c;
  const cd rt = std::sqrt(eps - sn * sn);
  const cd rv = (eps * c - rt) / (eps * c + rt);
  const cd rh = (c - rt) / (c + rt);
  const cd r0 = (std::sqrt(eps) - 1.0) / (std::sqrt(eps) + 1.0);
  const int terms = series_terms(4.0 * ksc * ksc);
  const double big_k = 2.0 * k * sn;  // the Bragg wavenumber

  // Transition function T_f (Wu et al. 2001).
  const cd ft = 8.0 * r0 * r0 * sn * (c + rt) / (c * rt);
  const double damp = std::exp(-ksc * ksc);
  double a1 = 0.0;
  double b1 = 0.0;
  double power = 1.0;  // (k s c)^(2n) / n!
  double two_n1 = 2.0;
  for (int n = 1; n <= terms; ++n) {
    power *= ksc * ksc / n;
    two_n1 *= 2.0;  // 2^(n+1)
    const double w = roughness_spectrum(gaussian, l, n, big_k);
    a1 += power * w;
    b1 += power * std::norm(ft / 2.0 + two_n1 * r0 / c * damp) * w;
  }
  const double tf = b1 > 0.0 ? 1.0 - 0.25 * a1 / b1 * std::norm(ft + 8.0 * r0 / c) : 0.0;
  const cd r = vertical ? rv : rh;
  const cd r_nadir = vertical ? r0 : -r0;
  const cd r_t = r + (r_nadir - r) * tf;
  const cd f = (vertical ? 2.0 : -2.0) * r_t / c;

  const cd rp = vertical ? rv : rh;  // the complementary fields use the Fresnel values
  const cd f_single = complementary_field(vertical, +1, true, eps, c, sn, rt, rp) +
                      complementary_field(vertical, -1, false, eps, c, sn, rt, rp);
  const cd f_series = complementary_field(vertical, -1, true, eps, c, sn, rt, rp) +
                      complementary_field(vertical, +1, false, eps, c, sn, rt, rp);
  const double ks = k * s;
  const double x = 2.0 * ksc;
  double sum = 0.0;
  double xn1 = 1.0;   // x^(n-1)
  double fact = 1.0;  // n!
  for (int n = 1; n <= terms; ++n) {
    fact *= n;
    cd term = xn1 * x * f + 0.25 * ks * f_series * xn1;
    if (n == 1) term += 0.25 * ks * f_single;
    sum += std::norm(term) * roughness_spectrum(gaussian, l, n, big_k) / fact;
    xn1 *= x;
  }
  const double rms_slope = (gaussian ? std::sqrt(2.0) : 1.0) * s / l;
  const double mu = sn > 0.0 ? c / sn / (std::sqrt(2.0) * rms_slope) : HUGE_VAL;
  const double shadow = 1.0 / (1.0 + 2.0 * smith_g(mu));
  return shadow * k * k / 2.0 * damp * damp * damp * damp * sum;
}

double i2em_crosspol(cd eps, double k, double s, double l, bool gaussian, double theta) {
  const double c = std::cos(theta);
  const double sn = std::sin(theta);
  const double ks2c2 = (k * s * c) * (k * s * c);
  const cd rt = std::sqrt(eps - sn * sn);
  const cd rv = (eps * c - rt) / (eps * c + rt);
  const cd rh = (c - rt) / (c + rt);
  const cd rvh = (rv - rh) / 2.0;
  const cd rp = 1.0 + rvh;
  const cd rm = 1.0 - rvh;
  const double kl2 = (k * l) * (k * l);
  const double rms_slope = (gaussian ? std::sqrt(2.0) : 1.0) * s / l;
  const int terms = series_terms(4.0 * ks2c2);

  // sum_n (k s c)^(2n)/n! w_n(rho^2), the spectra on the normalised plane.
  auto spectral_sum = [&](double rho2) {
    double sum = 0.0;
    double power = 1.0;
    for (int n = 1; n <= terms; ++n) {
      power *= ks2c2 / n;
      const double w = gaussian ? 0.5 * kl2 / n * std::exp(-kl2 * rho2 / (4.0 * n))
                                : n * kl2 / std::pow(n * n + kl2 * rho2, 1.5);
      sum += power * w;
    }
    return sum;
  };
  const double big_r = std::sqrt(1.0001);
  // Integrand over (u, phi) with r = R sin u: dr = R cos u du = q du.
  auto integrand = [&](double uu, double phi) {
    const double r = big_r * std::sin(uu);
    const double q = big_r * std::cos(uu);
    const double rx = r * std::cos(phi);
    const double ry = r * std::sin(phi);
    const cd qt = std::sqrt(eps - r * r);
    const cd a = rp / q;
    const cd b = rm / q;
    const cd cc = rp / qt;
    const cd d = rm / qt;
    const cd fvh1 = (b - cc) * (1.0 - 3.0 * rvh) - (b - cc / eps) * rp;
    const cd fvh2 = (a - d) * (1.0 + 3.0 * rvh) - (a - d * eps) * rm;
    const double fvh = std::norm((fvh1 + fvh2) * (rx * ry / c));
    const double au = q / (r * std::sqrt(2.0) * rms_slope);
    const double sha = 1.0 / (1.0 + smith_g(au));
    const double wn = spectral_sum((rx - sn) * (rx - sn) + ry * ry);
    const double wm = spectral_sum((rx + sn) * (rx + sn) + ry * ry);
    return fvh * wn * wm * r * sha * q;
  };
  using Gauss = boost::math::quadrature::gauss<double, 20>;
  // Two panels in u, the second over the last degrees where the r -> 1
  // edge (q -> 0) varies fastest.
  const double u0 = std::asin(0.1 / big_r);
  const double u2 = std::asin(1.0 / big_r);
  const double u1 = u2 - 0.15;
  auto over_phi = [&](double uu) {
    return Gauss::integrate([&](double phi) { return integrand(uu, phi); }, 0.0, kPi);
  };
  const double integral = Gauss::integrate(over_phi, u0, u1) + Gauss::integrate(over_phi, u1, u2);
  const double mu = sn > 0.0 ? c / sn / (std::sqrt(2.0) * rms_slope) : HUGE_VAL;
  const double shadow = 1.0 / (1.0 + smith_g(mu));
  return shadow * 4.0 * std::exp(-2.0 * ks2c2) / (16.0 * kPi) * integral;
}

class I2em final : public BackscatterModel {
 public:
  I2em(double s_m, double l_m, bool gaussian, SoilPermittivity eps, ModelContext ctx,
       std::string key)
      : s_m_(s_m),
        l_m_(l_m),
        gaussian_(gaussian),
        eps_(std::move(eps)),
        ctx_(std::move(ctx)),
        key_(std::move(key)) {}

  void check_band(const RadarBand& band) const override {
    const double ks = wavenumber_per_m(band.frequency_hz) * s_m_;
    if (ks > 3.0) {
      report_out_of_validity(ctx_, key_,
                             fmt::format("ks = {:.3f} at {:g} GHz is outside the I2EM's "
                                         "validity range ks <= 3",
                                         ks, band.frequency_hz / 1e9));
    }
    eps_.check_band(band.frequency_hz);
  }

  double sigma0(double incidence_rad, const RadarBand& band) const override {
    return i2em_sigma0(eps_.at(band.frequency_hz), wavenumber_per_m(band.frequency_hz), s_m_, l_m_,
                       gaussian_, incidence_rad, band.polarisation);
  }

  std::string describe() const override {
    return fmt::format(
        "i2em rms_height = {:g} cm, correlation_length = {:g} cm ({}), permittivity {}",
        s_m_ * 100.0, l_m_ * 100.0, gaussian_ ? "gaussian" : "exponential", eps_.describe());
  }

 private:
  double s_m_;
  double l_m_;
  bool gaussian_;
  SoilPermittivity eps_;
  ModelContext ctx_;
  std::string key_;
};

}  // namespace

double i2em_sigma0(std::complex<double> eps, double k_per_m, double rms_height_m,
                   double correlation_length_m, bool gaussian, double incidence_rad,
                   Polarisation pol) {
  // Grazing incidence: no return (the shadowing factor tends to 0).
  if (!(incidence_rad < kPi / 2.0)) return 0.0;
  if (pol == Polarisation::HV || pol == Polarisation::VH) {
    return i2em_crosspol(eps, k_per_m, rms_height_m, correlation_length_m, gaussian, incidence_rad);
  }
  return i2em_copol(eps, k_per_m, rms_height_m, correlation_length_m, gaussian, incidence_rad,
                    pol == Polarisation::VV);
}

std::unique_ptr<BackscatterModel> make_i2em(ConfigTable& params, const ModelContext& ctx) {
  const double s_m = params.get_quantity("rms_height", Quantity::length);
  if (!(s_m > 0.0)) params.fail("rms_height", "expected an rms height > 0");
  const double l_m = params.get_quantity("correlation_length", Quantity::length);
  if (!(l_m > 0.0)) params.fail("correlation_length", "expected a correlation length > 0");
  const bool gaussian =
      params.get_enum<bool>("correlation", {{"gaussian", true}, {"exponential", false}});
  SoilPermittivity eps = read_soil_permittivity(params, "permittivity", ctx);
  params.finish();
  return std::make_unique<I2em>(s_m, l_m, gaussian, std::move(eps), ctx,
                                params.key_path("rms_height"));
}

}  // namespace ris::detail
