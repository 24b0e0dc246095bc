// The ground permittivity a soil model uses (private to src/): a fixed
// complex value, or a dielectric model of moisture and texture evaluated at
// the band's frequency.
//
// TOML: either  permittivity = "15 - 4j"          (eps' - j eps'', eps'' >= 0)
//       or      [category.model.permittivity]
//               model = "dobson1985"   # or "hallikainen1985", "mironov2009"
//               moisture = 0.20        # volumetric, m3/m3
//               clay = 0.20            # mass fraction
//               sand = 0.40            # mass fraction
//               bulk_density = 1.5     # g/cm3, optional (dobson1985 only)
//               temperature = 20.0     # deg C, optional (dobson1985 only)
//               conductivity = "dobson1985"  # or "peplinski1995" (dobson1985 only)
#pragma once

#include <complex>
#include <optional>
#include <string>

#include "ris/backscatter/backscatter_model.h"
#include "ris/backscatter/dielectric.h"
#include "ris/backscatter/polarisation.h"
#include "ris/io/config_table.h"

namespace ris::detail {

class SoilPermittivity {
 public:
  explicit SoilPermittivity(std::complex<double> eps) : fixed_(eps) {}
  SoilPermittivity(DielectricModel model, SoilComposition soil, ModelContext ctx, std::string key)
      : model_(model), soil_(soil), ctx_(std::move(ctx)), key_(std::move(key)) {}

  // eps' - j eps'' at the frequency. Outside the dielectric model's frequency
  // range this is an extrapolation; check_band() reports it first.
  std::complex<double> at(double frequency_hz) const;
  void check_band(double frequency_hz) const;
  std::string describe() const;

 private:
  std::complex<double> fixed_{1.0, 0.0};
  std::optional<DielectricModel> model_;
  SoilComposition soil_;
  ModelContext ctx_;
  std::string key_;
};

SoilPermittivity read_soil_permittivity(ConfigTable& params, const std::string& key,
                                        const ModelContext& ctx);

// The model formulas themselves, shared with the tests.
double oh1992_sigma0(std::complex<double> eps, double ks, double incidence_rad, Polarisation pol);

// Oh 1992's terms that depend only on the band (eps, ks, polarisation), for a
// curve over many angles; oh1992_sigma0 above is oh1992_sigma0_at of these.
struct Oh1992BandTerms {
  std::complex<double> eps;
  double g0_exponent = 0.0;  // 1 / (3 G0)
  double e = 0.0;            // exp(-ks)
  double q = 0.0;
  double g = 0.0;
  Polarisation pol = Polarisation::HH;
};
Oh1992BandTerms oh1992_band_terms(std::complex<double> eps, double ks, Polarisation pol);
double oh1992_sigma0_at(const Oh1992BandTerms& t, double incidence_rad);

}  // namespace ris::detail
