// Oh 1992: semi-empirical backscatter of bare soil (HH, VV, HV).
//
// With G0 = |(1 - sqrt(eps)) / (1 + sqrt(eps))|^2 (nadir Fresnel
// reflectivity), Gh and Gv the Fresnel reflectivities at theta:
//   p  = sigma_hh / sigma_vv = [1 - (2 theta / pi)^(1 / (3 G0)) exp(-ks)]^2
//   q  = sigma_hv / sigma_vv = 0.23 sqrt(G0) (1 - exp(-ks))
//   g  = 0.7 [1 - exp(-0.65 (ks)^1.8)]
//   VV = g cos^3(theta) (Gv + Gh) / sqrt(p),   HH = p VV,   HV = VH = q VV
// Source: Oh, Y., Sarabandi, K. & Ulaby, F. T. (1992), "An empirical model and
// an inversion technique for radar scattering from bare soil surfaces", IEEE
// Trans. Geosci. Remote Sens. 30(2), 370-381, eqs. (3)-(5) and (8); MODEL.md
// section 4.
// Parameters:
//   rms_height    surface rms height s (length, "1 cm"); k s is formed with
//                 the band's wavenumber k = 2 pi f / c
//   permittivity  relative permittivity of the soil, "eps' - eps''j" with
//                 eps'' >= 0 (e.g. "15 - 4j"), or [permittivity] a dielectric
//                 model table (see docs/backscatter.md)
// Validity (the measurements the model was fitted to: 1.5, 4.75 and 9.5 GHz,
// 10-70 deg, 0.09 <= mv <= 0.31): 0.1 <= ks <= 6.0 is enforced at each band;
// the angle range is documented, not enforced, because a LUT spans 0-90 deg
// (the formula stays finite and tends to 0 at grazing incidence).
//
// TOML:  [category.model]
//        name = "oh1992"
//        rms_height = "1 cm"
//        permittivity = "15 - 4j"
#include "backscatter/models/models.h"
#include "backscatter/models/soil_permittivity.h"

namespace ris::detail {
namespace {

class Oh1992 final : public BackscatterModel {
 public:
  Oh1992(double rms_height_m, SoilPermittivity eps, ModelContext ctx, std::string key)
      : s_m_(rms_height_m), eps_(std::move(eps)), ctx_(std::move(ctx)), key_(std::move(key)) {}

  void check_band(const RadarBand& band) const override {
    const double ks = wavenumber_per_m(band.frequency_hz) * s_m_;
    if (ks < 0.1 || ks > 6.0) {
      report_out_of_validity(ctx_, key_,
                             fmt::format("ks = {:.3f} at {:g} GHz (rms_height = {:g} cm) is "
                                         "outside Oh 1992's validity range 0.1 <= ks <= 6.0",
                                         ks, band.frequency_hz / 1e9, s_m_ * 100.0));
    }
    eps_.check_band(band.frequency_hz);
  }

  double sigma0(double incidence_rad, const RadarBand& band) const override {
    const double ks = wavenumber_per_m(band.frequency_hz) * s_m_;
    const std::complex<double> eps = eps_.at(band.frequency_hz);
    return oh1992_sigma0(eps, ks, incidence_rad, band.polarisation);
  }

  // The permittivity (a dielectric model's many powers and exponentials) and
  // the other band terms once per curve, not per angle: the same values.
  void sigma0_curve(const double* incidence_rad, std::size_t n, const RadarBand& band,
                    double* out) const override {
    const double ks = wavenumber_per_m(band.frequency_hz) * s_m_;
    const Oh1992BandTerms t = oh1992_band_terms(eps_.at(band.frequency_hz), ks, band.polarisation);
    for (std::size_t i = 0; i < n; ++i) out[i] = oh1992_sigma0_at(t, incidence_rad[i]);
  }

  std::string describe() const override {
    return fmt::format("oh1992 rms_height = {:g} cm, permittivity {}", s_m_ * 100.0,
                       eps_.describe());
  }

 private:
  double s_m_;
  SoilPermittivity eps_;
  ModelContext ctx_;
  std::string key_;
};

}  // namespace

Oh1992BandTerms oh1992_band_terms(std::complex<double> eps, double ks, Polarisation pol) {
  Oh1992BandTerms t;
  t.eps = eps;
  const std::complex<double> root = std::sqrt(eps);
  const double g0 = std::norm((1.0 - root) / (1.0 + root));
  t.g0_exponent = 1.0 / (3.0 * g0);
  t.e = std::exp(-ks);
  t.q = 0.23 * std::sqrt(g0) * (1.0 - t.e);
  t.g = 0.7 * (1.0 - std::exp(-0.65 * std::pow(ks, 1.8)));
  t.pol = pol;
  return t;
}

double oh1992_sigma0_at(const Oh1992BandTerms& b, double theta) {
  // One sincos for the Fresnel terms and cos^3 (glibc's sincos gives
  // cos's bits).
  const double c = std::cos(theta);
  const Fresnel f = fresnel_reflectivity_cs(b.eps, c, std::sin(theta));
  const double t = 1.0 - std::pow(2.0 * theta / kPi, b.g0_exponent) * b.e;
  const double p = t * t;
  const double vv = b.g * c * c * c * (f.gv + f.gh) / std::sqrt(p);
  switch (b.pol) {
    case Polarisation::VV:
      return vv;
    case Polarisation::HH:
      return p * vv;
    case Polarisation::HV:
    case Polarisation::VH:
      return b.q * vv;
  }
  return vv;
}

double oh1992_sigma0(std::complex<double> eps, double ks, double theta, Polarisation pol) {
  return oh1992_sigma0_at(oh1992_band_terms(eps, ks, pol), theta);
}

std::unique_ptr<BackscatterModel> make_oh1992(ConfigTable& params, const ModelContext& ctx) {
  const double s_m = params.get_quantity("rms_height", Quantity::length);
  if (!(s_m > 0.0)) params.fail("rms_height", "expected an rms height > 0");
  SoilPermittivity eps = read_soil_permittivity(params, "permittivity", ctx);
  params.finish();
  return std::make_unique<Oh1992>(s_m, std::move(eps), ctx, params.key_path("rms_height"));
}

}  // namespace ris::detail
