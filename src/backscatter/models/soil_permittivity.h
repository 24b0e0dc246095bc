// The ground permittivity a soil model uses (private to src/): a fixed
// complex value, eps' - j eps'' with eps'' >= 0.
//
// TOML:  permittivity = "15 - 4j"
#pragma once

#include <complex>
#include <string>

#include "ris/backscatter/backscatter_model.h"
#include "ris/backscatter/polarisation.h"
#include "ris/io/config_table.h"

namespace ris::detail {

class SoilPermittivity {
 public:
  explicit SoilPermittivity(std::complex<double> eps) : fixed_(eps) {}
  std::complex<double> at(double /*frequency_hz*/) const { return fixed_; }
  void check_band(double /*frequency_hz*/) const {}
  std::string describe() const;

 private:
  std::complex<double> fixed_;
};

SoilPermittivity read_soil_permittivity(ConfigTable& params, const std::string& key,
                                        const ModelContext& ctx);

// The Oh 1992 formula itself (models/oh1992.cpp), shared with tests.
double oh1992_sigma0(std::complex<double> eps, double ks, double incidence_rad, Polarisation pol);

}  // namespace ris::detail
