// Small perturbation model (first order): backscatter of a slightly rough
// dielectric surface.
//
//   sigma_pp = 8 k^4 s^2 cos^4(t) |alpha_pp|^2 W(2 k sin t),   sigma_hv = 0
//   alpha_hh = (cos t - sqrt(eps - sin^2 t)) / (cos t + sqrt(eps - sin^2 t))
//   alpha_vv = (eps - 1)(sin^2 t - eps (1 + sin^2 t)) / (eps cos t + sqrt(eps - sin^2 t))^2
// with W the normalised roughness spectrum (Fourier transform / 2 pi of the
// surface correlation function):
//   gaussian     rho(r) = exp(-r^2/l^2):  W(K) = (l^2 / 2) exp(-(K l)^2 / 4)
//   exponential  rho(r) = exp(-r/l):      W(K) = l^2 / (1 + (K l)^2)^1.5
// Source: Rice (1951); in this form Ulaby, Moore & Fung (1982), Microwave
// Remote Sensing vol. II, section 12-4 (eqs. 12.54-12.56) and Fung (1994),
// Microwave Scattering and Emission Models, ch. 2.
// Parameters:
//   rms_height          s (length)
//   correlation_length  l (length)
//   correlation         "gaussian" or "exponential"
//   permittivity        "eps' - eps''j" or a dielectric table
// Validity: ks <= 0.3 (enforced per band) and rms slope sqrt(2) s / l <= 0.3
// (enforced when built); Ulaby, Moore & Fung vol. II, p. 961. First order
// gives no cross-polarised return: HV = VH = 0.
//
// TOML:  [category.model]
//        name = "spm"
//        rms_height = "0.4 cm"
//        correlation_length = "4 cm"
//        correlation = "exponential"
//        permittivity = "15 - 4j"
#include "backscatter/models/models.h"
#include "backscatter/models/soil_permittivity.h"

namespace ris::detail {

double spm_sigma0(std::complex<double> eps, double k, double s, double l, bool gaussian,
                  double theta, Polarisation pol) {
  if (pol == Polarisation::HV || pol == Polarisation::VH) return 0.0;
  const double c = std::cos(theta);
  const double sn = std::sin(theta);
  const std::complex<double> root = std::sqrt(eps - sn * sn);
  std::complex<double> alpha;
  if (pol == Polarisation::HH) {
    alpha = (c - root) / (c + root);
  } else {
    const std::complex<double> d = eps * c + root;
    alpha = (eps - 1.0) * (sn * sn - eps * (1.0 + sn * sn)) / (d * d);
  }
  const double kk = 2.0 * k * sn * l;  // K l with K = 2 k sin t
  const double w =
      gaussian ? 0.5 * l * l * std::exp(-kk * kk / 4.0) : l * l / std::pow(1.0 + kk * kk, 1.5);
  const double k2 = k * k;
  return 8.0 * k2 * k2 * s * s * c * c * c * c * std::norm(alpha) * w;
}

namespace {

class Spm final : public BackscatterModel {
 public:
  Spm(double s_m, double l_m, bool gaussian, SoilPermittivity eps, ModelContext ctx,
      std::string key)
      : s_m_(s_m),
        l_m_(l_m),
        gaussian_(gaussian),
        eps_(std::move(eps)),
        ctx_(std::move(ctx)),
        key_(std::move(key)) {}

  void check_band(const RadarBand& band) const override {
    const double ks = wavenumber_per_m(band.frequency_hz) * s_m_;
    if (ks > 0.3) {
      report_out_of_validity(ctx_, key_,
                             fmt::format("ks = {:.3f} at {:g} GHz is outside the small "
                                         "perturbation model's validity range ks <= 0.3",
                                         ks, band.frequency_hz / 1e9));
    }
    eps_.check_band(band.frequency_hz);
  }

  double sigma0(double incidence_rad, const RadarBand& band) const override {
    return spm_sigma0(eps_.at(band.frequency_hz), wavenumber_per_m(band.frequency_hz), s_m_, l_m_,
                      gaussian_, incidence_rad, band.polarisation);
  }

  std::string describe() const override {
    return fmt::format(
        "spm rms_height = {:g} cm, correlation_length = {:g} cm ({}), "
        "permittivity {}",
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

std::unique_ptr<BackscatterModel> make_spm(ConfigTable& params, const ModelContext& ctx) {
  const double s_m = params.get_quantity("rms_height", Quantity::length);
  if (!(s_m > 0.0)) params.fail("rms_height", "expected an rms height > 0");
  const double l_m = params.get_quantity("correlation_length", Quantity::length);
  if (!(l_m > 0.0)) params.fail("correlation_length", "expected a correlation length > 0");
  // Gaussian (true) or exponential (false) correlation function.
  const bool gaussian =
      params.get_enum<bool>("correlation", {{"gaussian", true}, {"exponential", false}});
  const double slope = std::sqrt(2.0) * s_m / l_m;
  if (slope > 0.3) {
    report_out_of_validity(ctx, params.key_path("correlation_length"),
                           fmt::format("rms slope sqrt(2) s / l = {:.3f} is outside the small "
                                       "perturbation model's validity range (<= 0.3)",
                                       slope));
  }
  SoilPermittivity eps = read_soil_permittivity(params, "permittivity", ctx);
  params.finish();
  return std::make_unique<Spm>(s_m, l_m, gaussian, std::move(eps), ctx,
                               params.key_path("rms_height"));
}

}  // namespace ris::detail
