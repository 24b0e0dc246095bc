// Lambert's law: a perfectly diffuse scatterer.
//
//   sigma0(theta) = gamma cos^2(theta)
//
// Source: the Lambertian surface of optics, as written for radar by Ulaby,
// Moore & Fung (1982), Microwave Remote Sensing vol. II, section 12-2;
// MODEL.md section 4. Parameters: gamma (linear, > 0), the value at nadir,
// or gamma_db (dB); one of the two.
// Validity: no frequency or polarisation dependence; choose gamma per band.
//
// TOML:  [category.model]
//        name = "lambert"
//        gamma_db = -10.0
#include "backscatter/models/models.h"

namespace ris::detail {
namespace {

class Lambert final : public BackscatterModel {
 public:
  explicit Lambert(double gamma) : gamma_(gamma) {}
  double sigma0(double incidence_rad, const RadarBand&) const override {
    const double c = std::cos(incidence_rad);
    return gamma_ * c * c;
  }
  std::string describe() const override {
    return fmt::format("lambert gamma = {:.2f} dB", linear_to_db(gamma_));
  }

 private:
  double gamma_;
};

}  // namespace

std::unique_ptr<BackscatterModel> make_lambert(ConfigTable& params, const ModelContext&) {
  const double gamma = get_linear_or_db(params, "gamma");
  params.finish();
  return std::make_unique<Lambert>(gamma);
}

}  // namespace ris::detail
