// Oh 2004: semi-empirical backscatter of bare soil from moisture and
// roughness (HH, VV, HV), no permittivity needed.
//
//   sigma_hv = 0.11 mv^0.7 cos^2.2(theta) [1 - exp(-0.32 (ks)^1.8)]
//   p = sigma_hh / sigma_vv = 1 - (2 theta / pi)^(0.35 mv^-0.65) exp(-0.4 (ks)^1.4)
//   q = sigma_hv / sigma_vv = 0.095 (0.13 + sin 1.5 theta)^1.4 [1 - exp(-1.3 (ks)^0.9)]
//   VV = sigma_hv / q,   HH = p VV,   HV = VH = sigma_hv
// Source: Oh, Y. (2004), "Quantitative retrieval of soil moisture content and
// surface roughness from multipolarized radar observations of bare soil
// surfaces", IEEE Trans. Geosci. Remote Sens. 42(3), 596-601, eqs. (1)-(3)
// (as restated in Ulaby & Long 2014, Microwave Radar and Radiometric Remote
// Sensing, sec. 10-5).
// Parameters:
//   rms_height  surface rms height s (length, "1 cm"); ks with the band's
//               wavenumber k = 2 pi f / c
//   moisture    volumetric soil moisture mv (m3/m3)
// Validity (the data the model was fitted to: 1.25, 4.75 and 9.5 GHz,
// 10-70 deg): 0.13 <= ks <= 6.98 and 0.04 <= mv <= 0.291, enforced at each
// band (refused naming the range unless allow_extrapolation = true); the
// angle range is documented, not enforced (a LUT spans 0-90 deg; the formula
// stays finite, HV and VV tend to 0 at grazing incidence).
//
// TOML:  [category.model]
//        name = "oh2004"
//        rms_height = "1 cm"
//        moisture = 0.2
#include "backscatter/models/models.h"

namespace ris::detail {

double oh2004_sigma0(double mv, double ks, double theta, Polarisation pol) {
  const double c = std::cos(theta);
  const double hv =
      0.11 * std::pow(mv, 0.7) * std::pow(c, 2.2) * (1.0 - std::exp(-0.32 * std::pow(ks, 1.8)));
  if (pol == Polarisation::HV || pol == Polarisation::VH) return hv;
  const double q = 0.095 * std::pow(0.13 + std::sin(1.5 * theta), 1.4) *
                   (1.0 - std::exp(-1.3 * std::pow(ks, 0.9)));
  const double vv = hv / q;
  if (pol == Polarisation::VV) return vv;
  const double p = 1.0 - std::pow(2.0 * theta / kPi, 0.35 * std::pow(mv, -0.65)) *
                             std::exp(-0.4 * std::pow(ks, 1.4));
  return p * vv;
}

namespace {

class Oh2004 final : public BackscatterModel {
 public:
  Oh2004(double rms_height_m, double mv, ModelContext ctx, std::string key)
      : s_m_(rms_height_m), mv_(mv), ctx_(std::move(ctx)), key_(std::move(key)) {}

  void check_band(const RadarBand& band) const override {
    const double ks = wavenumber_per_m(band.frequency_hz) * s_m_;
    if (ks < 0.13 || ks > 6.98) {
      report_out_of_validity(ctx_, key_,
                             fmt::format("ks = {:.3f} at {:g} GHz (rms_height = {:g} cm) is "
                                         "outside Oh 2004's validity range 0.13 <= ks <= 6.98",
                                         ks, band.frequency_hz / 1e9, s_m_ * 100.0));
    }
  }

  double sigma0(double incidence_rad, const RadarBand& band) const override {
    const double ks = wavenumber_per_m(band.frequency_hz) * s_m_;
    return oh2004_sigma0(mv_, ks, incidence_rad, band.polarisation);
  }

  std::string describe() const override {
    return fmt::format("oh2004 rms_height = {:g} cm, moisture = {:g} m3/m3", s_m_ * 100.0, mv_);
  }

 private:
  double s_m_;
  double mv_;
  ModelContext ctx_;
  std::string key_;
};

}  // namespace

std::unique_ptr<BackscatterModel> make_oh2004(ConfigTable& params, const ModelContext& ctx) {
  const double s_m = params.get_quantity("rms_height", Quantity::length);
  if (!(s_m > 0.0)) params.fail("rms_height", "expected an rms height > 0");
  const double mv = params.get_double("moisture");
  if (!(mv > 0.0 && mv < 1.0)) {
    params.fail("moisture", "expected a volumetric water content in (0, 1) m3/m3");
  }
  if (mv < 0.04 || mv > 0.291) {
    report_out_of_validity(
        ctx, params.key_path("moisture"),
        fmt::format("moisture = {:g} m3/m3 is outside Oh 2004's validity range 0.04-0.291", mv));
  }
  params.finish();
  return std::make_unique<Oh2004>(s_m, mv, ctx, params.key_path("rms_height"));
}

}  // namespace ris::detail
