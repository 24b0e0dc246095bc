// Dubois 1995: empirical backscatter of bare soil (HH and VV).
//
//   HH = 10^-2.75 cos^1.5(t) / sin^5(t) 10^(0.028 eps' tan t) (ks sin t)^1.4 lambda^0.7
//   VV = 10^-2.35 cos^3(t) / sin^3(t)   10^(0.046 eps' tan t) (ks sin t)^1.1 lambda^0.7
// with lambda the wavelength in centimetres and eps' the real part of the
// soil permittivity.
// Source: Dubois, P. C., van Zyl, J. & Engman, T. (1995), "Measuring soil
// moisture with imaging radars", IEEE Trans. Geosci. Remote Sens. 33(4),
// 915-926, eqs. (1)-(2); restated in Ulaby & Long (2014), Microwave Radar and
// Radiometric Remote Sensing, eq. (10.41).
// Parameters:
//   rms_height    surface rms height s (length, "1 cm")
//   permittivity  "eps' - eps''j" or a dielectric table (only eps' is used)
// Validity (the paper's): ks <= 2.5, 1.5-11 GHz (enforced per band),
// mv <= 0.35, incidence >= 30 deg. The formula diverges towards nadir, so
// below 30 deg it is refused; with allow_extrapolation = true it is held at
// its 30 deg value there. Cross-polarisation is not modelled: HV and VH are
// an error.
//
// TOML:  [category.model]
//        name = "dubois1995"
//        rms_height = "1 cm"
//        permittivity = "15 - 4j"
#include "backscatter/models/models.h"
#include "backscatter/models/soil_permittivity.h"
#include "ris/util/error.h"

namespace ris::detail {

double dubois1995_sigma0(double eps_re, double ks, double wavelength_cm, double theta,
                         Polarisation pol) {
  const double c = std::cos(theta);
  const double s = std::sin(theta);
  const double t = std::tan(theta);
  if (pol == Polarisation::HH) {
    return std::pow(10.0, -2.75) * std::pow(c, 1.5) / std::pow(s, 5.0) *
           std::pow(10.0, 0.028 * eps_re * t) * std::pow(ks * s, 1.4) *
           std::pow(wavelength_cm, 0.7);
  }
  return std::pow(10.0, -2.35) * (c * c * c) / (s * s * s) * std::pow(10.0, 0.046 * eps_re * t) *
         std::pow(ks * s, 1.1) * std::pow(wavelength_cm, 0.7);
}

namespace {

constexpr double kMinAngleRad = 30.0 * kPi / 180.0;

class Dubois1995 final : public BackscatterModel {
 public:
  Dubois1995(double s_m, SoilPermittivity eps, ModelContext ctx, std::string key)
      : s_m_(s_m), eps_(std::move(eps)), ctx_(std::move(ctx)), key_(std::move(key)) {}

  void check_band(const RadarBand& band) const override {
    if (band.polarisation == Polarisation::HV || band.polarisation == Polarisation::VH) {
      throw InputError(ctx_.file, key_,
                       "the dubois1995 model gives HH and VV only (no cross-polarisation); use "
                       "oh1992 for HV");
    }
    const double f_ghz = band.frequency_hz / 1e9;
    if (f_ghz < 1.5 || f_ghz > 11.0) {
      report_out_of_validity(ctx_, key_,
                             fmt::format("{:g} GHz is outside Dubois 1995's validity range "
                                         "1.5-11 GHz",
                                         f_ghz));
    }
    const double ks = wavenumber_per_m(band.frequency_hz) * s_m_;
    if (ks > 2.5) {
      report_out_of_validity(ctx_, key_,
                             fmt::format("ks = {:.3f} at {:g} GHz is outside Dubois 1995's "
                                         "validity range ks <= 2.5",
                                         ks, f_ghz));
    }
    eps_.check_band(band.frequency_hz);
  }

  double sigma0(double incidence_rad, const RadarBand& band) const override {
    double theta = incidence_rad;
    if (theta < kMinAngleRad) {
      report_out_of_validity(ctx_, key_,
                             "incidence below 30 deg is outside Dubois 1995's validity range "
                             "(>= 30 deg; held at the 30 deg value when extrapolating)");
      theta = kMinAngleRad;
    }
    const double ks = wavenumber_per_m(band.frequency_hz) * s_m_;
    const double lambda_cm = 100.0 * kSpeedOfLight_m_per_s / band.frequency_hz;
    return dubois1995_sigma0(eps_.at(band.frequency_hz).real(), ks, lambda_cm, theta,
                             band.polarisation);
  }

  std::string describe() const override {
    return fmt::format("dubois1995 rms_height = {:g} cm, permittivity {}", s_m_ * 100.0,
                       eps_.describe());
  }

 private:
  double s_m_;
  SoilPermittivity eps_;
  ModelContext ctx_;
  std::string key_;
};

}  // namespace

std::unique_ptr<BackscatterModel> make_dubois1995(ConfigTable& params, const ModelContext& ctx) {
  const double s_m = params.get_quantity("rms_height", Quantity::length);
  if (!(s_m > 0.0)) params.fail("rms_height", "expected an rms height > 0");
  SoilPermittivity eps = read_soil_permittivity(params, "permittivity", ctx);
  params.finish();
  return std::make_unique<Dubois1995>(s_m, std::move(eps), ctx, params.key_path("rms_height"));
}

}  // namespace ris::detail
