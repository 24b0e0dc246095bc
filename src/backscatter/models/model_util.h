// Helpers shared by the backscatter model files (private to src/).
#pragma once

#include <cmath>
#include <complex>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "ris/backscatter/backscatter_model.h"
#include "ris/io/config_table.h"
#include "ris/util/units.h"

namespace ris::detail {

inline double db_to_linear(double db) {
  return std::pow(10.0, db / 10.0);
}
inline double linear_to_db(double linear) {
  return 10.0 * std::log10(linear);
}

// Free-space wavenumber k = 2 pi f / c (rad/m).
inline double wavenumber_per_m(double frequency_hz) {
  return 2.0 * kPi * frequency_hz / kSpeedOfLight_m_per_s;
}

// Reads a value that must lie in [lo, hi] for the model to be valid; outside
// it, report_out_of_validity names the key and the range.
inline void check_range(const ModelContext& ctx, const ConfigTable& t, const std::string& key,
                        double value, double lo, double hi, const std::string& unit,
                        const std::string& model) {
  if (value >= lo && value <= hi) return;
  report_out_of_validity(ctx, t.key_path(key),
                         fmt::format("{} = {:g}{} is outside the {} model's validity range "
                                     "[{:g}, {:g}]{}",
                                     key, value, unit, model, lo, hi, unit));
}

// A parameter that must be >= 0 (or > 0): a plain InputError, not a
// validity-range question (negative values have no meaning).
double get_nonnegative(ConfigTable& t, const std::string& key);
double get_positive(ConfigTable& t, const std::string& key);

// A reflectivity written as linear ("gamma = 0.1") or in dB ("gamma_db = -10"):
// exactly one of the two keys. Returns linear.
double get_linear_or_db(ConfigTable& t, const std::string& key);

// Parses "15 - 4j" (eps' - j eps'', eps'' >= 0) into std::complex(15, -4).
// A positive imaginary part is the wrong sign for the convention and an
// error naming the key; so is eps' < 1.
std::complex<double> parse_permittivity(const ConfigTable& t, const std::string& key,
                                        const std::string& text);

// Fresnel power reflectivities |r_h|^2 and |r_v|^2 of a half space of
// relative permittivity eps at incidence theta (Ulaby, Moore & Fung 1981,
// Microwave Remote Sensing vol. I, eqs. 2.54-2.55).
struct Fresnel {
  double gh;
  double gv;
};
Fresnel fresnel_reflectivity(std::complex<double> eps, double incidence_rad);
// The same from the incidence's cosine and sine, for a caller that needs the
// cosine too (one sincos per angle in a LUT build, not a sincos and a cos).
Fresnel fresnel_reflectivity_cs(std::complex<double> eps, double cos_incidence,
                                double sin_incidence);

}  // namespace ris::detail
