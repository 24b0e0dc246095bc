// The factories of every registered backscatter model (private to src/).
// Each is defined in its own file, src/backscatter/models/<name>.cpp, with the
// model's documentation at the top; model_registry.cpp lists them by name.
#pragma once

#include <cmath>
#include <memory>

#include <fmt/format.h>

#include "backscatter/models/model_util.h"
#include "ris/backscatter/backscatter_model.h"
#include "ris/io/config_table.h"

namespace ris::detail {

using ModelFactory = std::unique_ptr<BackscatterModel> (*)(ConfigTable&, const ModelContext&);

std::unique_ptr<BackscatterModel> make_table_model(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_muhleman(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_constant_gamma(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_lambert(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_oh1992(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_water_cloud(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_dubois1995(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_spm(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_ulaby_dobson(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_oh2004(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_i2em(ConfigTable&, const ModelContext&);
std::unique_ptr<BackscatterModel> make_morchin(ConfigTable&, const ModelContext&);

// The formulas, shared with the tests (each in its model's file).
double dubois1995_sigma0(double eps_re, double ks, double wavelength_cm, double incidence_rad,
                         Polarisation pol);
double spm_sigma0(std::complex<double> eps, double k_per_m, double rms_height_m,
                  double correlation_length_m, bool gaussian, double incidence_rad,
                  Polarisation pol);
double oh2004_sigma0(double mv, double ks, double incidence_rad, Polarisation pol);
// Morchin's land clutter model (morchin.cpp): A, B, beta0 of a terrain, the
// desert's critical-angle rule, grazing angle psi (rad).
double morchin_sigma0(double a, double b_rad, double beta0_rad, bool desert, double frequency_hz,
                      double grazing_rad);
double i2em_sigma0(std::complex<double> eps, double k_per_m, double rms_height_m,
                   double correlation_length_m, bool gaussian, double incidence_rad,
                   Polarisation pol);

}  // namespace ris::detail
