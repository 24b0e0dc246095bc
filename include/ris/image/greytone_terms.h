// The factors of the seed's equation 15 and their switches (the seed's
// PROCES(5..13)): how the simulation turns a term off.
//
// Equation 15 (seed report, section 2; MODEL.md section 3):
//   G = G_ref + (255/X) [ gamma log10(P / P_ref) + log10(k2/k1) + gamma log10(M2/M1) ] + G_fad
//   P / P_ref = (P_T2/P_T1) (sigma0_2/sigma0_1) (dA_2/dA_1) (G_2^2/G_1^2)
//               (lambda_2^2/lambda_1^2) (R_1^4/R_2^4)
// A switched-off factor takes its reference value, so its ratio is one.
//
// Design (agreed with the image-formation side): the simulation computes the
// mean power P with the switched-off radar-equation factors already replaced
// by the reference cell's values, and the greytone stage (ris/image/greytone.h)
// only adds the k and M terms (switched there) and fading (switched by not
// applying it). switched_terms() says what to replace:
//   transmit power off  -> form the image with P_T1 instead of P_t
//   wavelength off      -> with lambda_1 instead of lambda
//   antenna gain off    -> with peak gain G_1 and a uniform elevation pattern
//                          (G = G_1 for every element)
//   backscatter off     -> with sigma0_1 for every category and angle
//                          (ConstantSigma0 below, through the usual Sigma0Lut)
//   range off           -> multiply each pixel of bin k by (R_k / R_1)^4, R_k
//                          the bin's centre range (range_correction()): the
//                          pixel then carries R_1^-4; the residual is the
//                          variation of R^-4 inside one bin (4 dr / R, 0.3% for
//                          the seed's radars), as the seed's one R per cell
//   area off            -> multiply each pixel by dA_1 / (the summed true area
//                          of the elements in it) (area_correction()): the
//                          pixel's area becomes dA_1, its other factors an
//                          area-weighted mean over the cell
// Fading off: do not apply ris/image/speckle.h. k or M off: GreytoneMap
// (greytone.h) leaves the term out.
//
// Example:
//   ris::resolve_reference_sigma0(radar, lut);       // if given as category + angle
//   ris::SwitchedRadarTerms t = ris::switched_terms(radar);
//   imaging.transmit_power_w = t.transmit_power_w;   // and wavelength, peak gain, ...
//   if (t.uniform_elevation) imaging.elevation_gain = {};
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/backscatter/sigma0_source.h"
#include "ris/sensor/radar_params.h"

namespace ris {

// The seed's equations 1 and 3: mean received power of one cell,
//   P = P_T sigma0 A G^2 lambda^2 / ((4 pi)^3 R^4),
// G the one-way antenna gain (linear). Watts.
double radar_equation_power_w(double transmit_power_w, double sigma0, double area_m2,
                              double gain_one_way, double wavelength_m, double range_m);

// P_ref of the reference cell: `mean_power_w` when given, else equation 3 with
// its factors. reference.sigma0 must be resolved (resolve_reference_sigma0).
double reference_power_w(const ReferenceCell& reference);

// When the reference sigma0 is given as a category at a local incidence
// angle, evaluates it in `lut` and stores it in radar.reference.sigma0; no-op
// otherwise. InputError (file radar.source_file, key reference.category) when
// the lut lacks the category: build the lut with that category included.
void resolve_reference_sigma0(RadarParams& radar, const Sigma0Lut& lut);

// The radar-equation inputs for forming the image, switched-off factors
// replaced by the reference cell's (see the design above).
struct SwitchedRadarTerms {
  double transmit_power_w = 0.0;            // P_t, or P_T1
  double wavelength_m = 0.0;                // lambda, or lambda_1
  double peak_gain = 1.0;                   // boresight one-way gain, or G_1
  bool uniform_elevation = false;           // antenna gain off: G_e = 1
  std::optional<double> constant_sigma0;    // backscatter off: sigma0_1
  std::optional<double> reference_range_m;  // range off: R_1
  std::optional<double> reference_area_m2;  // area off: dA_1
};
SwitchedRadarTerms switched_terms(const RadarParams& radar);

// Pixel factor for the range term: (R / R_1)^4 when switched off, else 1.
inline double range_correction(const SwitchedRadarTerms& t, double bin_centre_range_m) {
  if (!t.reference_range_m) return 1.0;
  const double q = bin_centre_range_m / *t.reference_range_m;
  return (q * q) * (q * q);
}

// Pixel factor for the area term: dA_1 / summed_area when switched off (0 for
// an empty pixel), else 1.
inline double area_correction(const SwitchedRadarTerms& t, double summed_area_m2) {
  if (!t.reference_area_m2) return 1.0;
  return summed_area_m2 > 0.0 ? *t.reference_area_m2 / summed_area_m2 : 0.0;
}

// A Sigma0Source that returns one value for every category and angle: the
// backscatter term switched off.
class ConstantSigma0 final : public Sigma0Source {
 public:
  explicit ConstantSigma0(double sigma0) : sigma0_(sigma0) {}
  bool has_category(std::uint16_t) const override { return true; }
  double sigma0(std::uint16_t, double, const RadarBand&) const override { return sigma0_; }
  std::string category_name(std::uint16_t category) const override;
  std::string description() const override;

 private:
  double sigma0_;
};

}  // namespace ris
