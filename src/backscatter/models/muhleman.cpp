// Muhleman's law: backscatter of a rough natural surface with no parameters.
//
//   sigma0(theta) = 0.0118 cos(theta) / (sin(theta) + 0.111 cos(theta))^3
//
// Source: Muhleman, D. O. (1964), "Radar scattering from Venus and the Moon",
// Astronomical Journal 69(1), 34-41; used for terrain by the Kansas simulator
// line of work and written in this form in MODEL.md section 4.
// Validity: an empirical law fitted to planetary radar echoes (decimetre
// wavelengths); it has no frequency or polarisation dependence, so ris
// accepts it at any band and polarisation. It peaks near nadir (at
// 0 deg: +9.36 dB) and falls to -13.17 dB at 30 deg and -21.23 dB at 60 deg.
//
// TOML:  [category.model]
//        name = "muhleman"        # no other keys
#include "backscatter/models/models.h"

namespace ris::detail {
namespace {

class Muhleman final : public BackscatterModel {
 public:
  double sigma0(double incidence_rad, const RadarBand&) const override {
    const double c = std::cos(incidence_rad);
    const double s = std::sin(incidence_rad);
    const double d = s + 0.111 * c;
    return 0.0118 * c / (d * d * d);
  }
  std::string describe() const override { return "muhleman"; }
};

}  // namespace

std::unique_ptr<BackscatterModel> make_muhleman(ConfigTable& params, const ModelContext&) {
  params.finish();
  return std::make_unique<Muhleman>();
}

}  // namespace ris::detail
