// Constant gamma (Clapp's model 3): the backscatter per unit area projected
// normal to the beam is constant.
//
//   sigma0(theta) = gamma cos(theta)
//
// Source: Clapp, R. E. (1946), "A theoretical and experimental study of radar
// ground return", MIT Radiation Laboratory Report 1024; MODEL.md section 4.
// The seed's second study used Clapp's model to extend measured data.
// Parameters: gamma (linear, > 0) or gamma_db (dB); one of the two.
// Validity: a crude fit for vegetation at intermediate angles (about 20-70
// deg); it has no frequency or polarisation dependence, so gamma must be
// chosen for the band (use per-band entries in the library).
//
// TOML:  [category.model]
//        name = "constant_gamma"
//        gamma_db = -12.0
#include "backscatter/models/models.h"

namespace ris::detail {
namespace {

class ConstantGamma final : public BackscatterModel {
 public:
  explicit ConstantGamma(double gamma) : gamma_(gamma) {}
  double sigma0(double incidence_rad, const RadarBand&) const override {
    return gamma_ * std::cos(incidence_rad);
  }
  std::string describe() const override {
    return fmt::format("constant_gamma gamma = {:.2f} dB", linear_to_db(gamma_));
  }

 private:
  double gamma_;
};

}  // namespace

std::unique_ptr<BackscatterModel> make_constant_gamma(ConfigTable& params, const ModelContext&) {
  const double gamma = get_linear_or_db(params, "gamma");
  params.finish();
  return std::make_unique<ConstantGamma>(gamma);
}

}  // namespace ris::detail
