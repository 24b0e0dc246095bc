#include "ris/image/greytone_terms.h"

#include <fmt/format.h>

#include <cmath>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

double radar_equation_power_w(double transmit_power_w, double sigma0, double area_m2,
                              double gain_one_way, double wavelength_m, double range_m) {
  // Seed equation 1: P = P_T sigma0 A G^2 lambda^2 / ((4 pi)^3 R^4).
  const double four_pi_cubed = 64.0 * kPi * kPi * kPi;
  const double r2 = range_m * range_m;
  return transmit_power_w * sigma0 * area_m2 * gain_one_way * gain_one_way * wavelength_m *
         wavelength_m / (four_pi_cubed * r2 * r2);
}

double reference_power_w(const ReferenceCell& ref) {
  if (ref.mean_power_w) return *ref.mean_power_w;
  return radar_equation_power_w(ref.transmit_power_w, ref.sigma0, ref.area_m2, ref.gain,
                                ref.wavelength_m, ref.range_m);
}

void resolve_reference_sigma0(RadarParams& radar, const Sigma0Lut& lut) {
  if (!radar.reference.sigma0_category) return;
  const std::uint16_t c = *radar.reference.sigma0_category;
  if (!lut.has(c)) {
    throw InputError(radar.source_file, "reference.category",
                     fmt::format("the backscatter table has no category {} for the reference "
                                 "cell",
                                 c));
  }
  radar.reference.sigma0 =
      static_cast<double>(lut.at(c, static_cast<float>(radar.reference.sigma0_incidence_rad)));
}

SwitchedRadarTerms switched_terms(const RadarParams& radar) {
  const GreytoneSwitches& sw = radar.switches;
  const ReferenceCell& ref = radar.reference;
  SwitchedRadarTerms t;
  t.transmit_power_w = sw.transmit_power ? radar.transmit_power_w : ref.transmit_power_w;
  t.wavelength_m = sw.wavelength ? radar.wavelength_m() : ref.wavelength_m;
  t.peak_gain = sw.antenna_gain ? radar.peak_gain : ref.gain;
  t.uniform_elevation = !sw.antenna_gain;
  if (!sw.backscatter) {
    // A category reference must have been resolved (resolve_reference_sigma0).
    RIS_CHECK(!std::isnan(ref.sigma0));
    t.constant_sigma0 = ref.sigma0;
  }
  if (!sw.range) t.reference_range_m = ref.range_m;
  if (!sw.area) t.reference_area_m2 = ref.area_m2;
  return t;
}

std::string ConstantSigma0::category_name(std::uint16_t category) const {
  return fmt::format("{}", category);
}

std::string ConstantSigma0::description() const {
  return fmt::format("constant sigma0 = {:g} (backscatter term of equation 15 switched off)",
                     sigma0_);
}

}  // namespace ris
