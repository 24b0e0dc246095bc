// Constant gamma (Clapp's model 3): the backscatter per unit area projected
// normal to the beam is constant.
//
//   sigma0(theta) = gamma cos(theta)      (= gamma sin(psi), psi grazing)
//
// Source: Clapp, R. E. (1946), "A theoretical and experimental study of radar
// ground return", MIT Radiation Laboratory Report 1024; MODEL.md section 4.
// The seed's second study used Clapp's model to extend measured data.
// Parameters: gamma (linear, > 0) or gamma_db (dB); one of the two.
// Optional frequency rule (both keys or neither):
//   reference_frequency   the frequency gamma is given at ("10 GHz")
//   db_per_decade         gamma_dB(f) = gamma_dB + db_per_decade log10(f / f_ref)
// The terrain values of Long (2001) and Nathanson et al. (1999) are given at
// 10 GHz with db_per_decade = 5 (MathWorks surfacegamma; data/backscatter/
// constant-gamma-terrain.toml); the rule carries no range of its own, so
// state the band it is used over with valid_frequency.
// Validity: a crude fit for vegetation at intermediate angles (about 20-70
// deg); without the frequency rule it has no frequency or polarisation
// dependence, so gamma must be chosen for the band (use per-band entries in
// the library).
//
// TOML:  [category.model]
//        name = "constant_gamma"
//        gamma_db = -12.0
#include "backscatter/models/models.h"

namespace ris::detail {
namespace {

class ConstantGamma final : public BackscatterModel {
 public:
  ConstantGamma(double gamma, double reference_hz, double db_per_decade)
      : gamma_(gamma), reference_hz_(reference_hz), db_per_decade_(db_per_decade) {}
  double sigma0(double incidence_rad, const RadarBand& band) const override {
    return gamma_at(band.frequency_hz) * std::cos(incidence_rad);
  }
  std::string describe() const override {
    if (reference_hz_ <= 0.0) {
      return fmt::format("constant_gamma gamma = {:.2f} dB", linear_to_db(gamma_));
    }
    return fmt::format("constant_gamma gamma = {:.2f} dB at {:g} GHz, {:+g} dB per decade",
                       linear_to_db(gamma_), reference_hz_ / 1e9, db_per_decade_);
  }

 private:
  double gamma_at(double frequency_hz) const {
    if (reference_hz_ <= 0.0) return gamma_;
    return gamma_ * std::pow(frequency_hz / reference_hz_, db_per_decade_ / 10.0);
  }
  double gamma_;
  double reference_hz_;  // 0: no frequency rule
  double db_per_decade_;
};

}  // namespace

std::unique_ptr<BackscatterModel> make_constant_gamma(ConfigTable& params, const ModelContext&) {
  const double gamma = get_linear_or_db(params, "gamma");
  double reference_hz = 0.0, db_per_decade = 0.0;
  if (params.has("reference_frequency") != params.has("db_per_decade")) {
    params.fail(params.has("db_per_decade") ? "db_per_decade" : "reference_frequency",
                "the frequency rule needs both reference_frequency and db_per_decade");
  }
  if (params.has("reference_frequency")) {
    reference_hz = params.get_quantity("reference_frequency", Quantity::frequency);
    if (!(reference_hz > 0.0)) params.fail("reference_frequency", "expected a frequency > 0");
    db_per_decade = params.get_double("db_per_decade");
  }
  params.finish();
  return std::make_unique<ConstantGamma>(gamma, reference_hz, db_per_decade);
}

}  // namespace ris::detail
