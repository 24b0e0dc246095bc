#include "ris/sensors_eo/facet_forcing.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace ris {
namespace {

constexpr double kPi = std::numbers::pi;

DiurnalForcing forcing_of(const DaySamples& day, const Vec3& n) {
  std::vector<double> insolation(day.t_seconds.size());
  for (std::size_t k = 0; k < insolation.size(); ++k) {
    insolation[k] = day.irradiance_w_m2[k] * std::max(0.0, n.dot(day.sun_enu[k]));
  }
  DiurnalForcing f;
  forcing_from_insolation(day, insolation.data(), f);
  return f;
}

// At the equator on the equinox the sun crosses the sky in the east-west
// vertical plane: level ground sees S cos(w t') for |w t'| < pi/2, a clipped
// cosine of mean S / pi and harmonics S / 2, 2 S / (3 pi); an east-facing
// wall sees S sin(w t') in the morning only, mean S / (2 pi) (with S the
// day's solar irradiance). The declination moves by 0.4 deg over the day,
// the 30-minute samples alias the clipped cosine's kinks: 0.3 % tolerance.
TEST(FacetForcing, EquatorEquinoxClosedForms) {
  const DaySamples day = day_samples({2024, 3, 20, 0.0}, 0.0, 0.0, 4, 1.0);
  double s = 0;
  for (double e : day.irradiance_w_m2) s = std::max(s, e);
  const DiurnalForcing flat = forcing_of(day, {0, 0, 1});
  EXPECT_NEAR(flat.mean_w_m2, s / kPi, 3e-3 * s / kPi);
  EXPECT_NEAR(std::abs(flat.harmonics_w_m2[0]), s / 2, 3e-3 * s / 2);
  EXPECT_NEAR(std::abs(flat.harmonics_w_m2[1]), 2 * s / (3 * kPi), 3e-3 * 2 * s / (3 * kPi));
  EXPECT_NEAR(std::abs(flat.harmonics_w_m2[2]), 0.0, 3e-3 * s);  // odd n > 1 vanish
  const DiurnalForcing east = forcing_of(day, {1, 0, 0});
  const DiurnalForcing west = forcing_of(day, {-1, 0, 0});
  EXPECT_NEAR(east.mean_w_m2, s / (2 * kPi), 3e-3 * s / (2 * kPi));
  EXPECT_NEAR(east.mean_w_m2 + west.mean_w_m2, s / kPi, 3e-3 * s / kPi);
  // The east wall's first harmonic: (1 / pi) int_{-pi/2}^0 -sin p e^{-i p} dp
  // S = S (1/2 + i pi/4) / pi relative to the flat ground's phase: a lead of
  // atan(pi / 2) (3.8 h: the wall is warmest in the morning).
  EXPECT_NEAR(std::abs(east.harmonics_w_m2[0]), s * std::hypot(0.5, kPi / 4) / kPi, 3e-3 * s / kPi);
  const double lead = std::arg(east.harmonics_w_m2[0] / flat.harmonics_w_m2[0]);
  EXPECT_NEAR(lead, std::atan(kPi / 2), 0.01);
}

}  // namespace
}  // namespace ris
