#include "backscatter/models/model_util.h"

#include <regex>

namespace ris::detail {

double get_nonnegative(ConfigTable& t, const std::string& key) {
  const double v = t.get_double(key);
  if (!(v >= 0.0)) t.fail(key, fmt::format("expected a number >= 0, got {:g}", v));
  return v;
}

double get_positive(ConfigTable& t, const std::string& key) {
  const double v = t.get_double(key);
  if (!(v > 0.0)) t.fail(key, fmt::format("expected a number > 0, got {:g}", v));
  return v;
}

double get_linear_or_db(ConfigTable& t, const std::string& key) {
  const std::string db_key = key + "_db";
  const bool lin = t.has(key);
  const bool db = t.has(db_key);
  if (lin == db) {
    t.fail(key, fmt::format("give exactly one of '{}' (linear) and '{}' (dB)", key, db_key));
  }
  if (lin) return get_positive(t, key);
  return db_to_linear(t.get_double(db_key));
}

std::complex<double> parse_permittivity(const ConfigTable& t, const std::string& key,
                                        const std::string& text) {
  // "a", "a - bj", "a + bj" (the last only to name the sign error).
  static const std::regex re(
      R"(^\s*([0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?)\s*(?:([+-])\s*([0-9]*\.?[0-9]+(?:[eE][+-]?[0-9]+)?)\s*[jJ])?\s*$)");
  std::smatch m;
  if (!std::regex_match(text, m, re)) {
    t.fail(key,
           fmt::format("expected a complex permittivity \"eps' - eps''j\" such as \"15 - 4j\", "
                       "got \"{}\"",
                       text));
  }
  const double re_part = std::stod(m[1].str());
  double im_part = 0.0;
  if (m[2].matched) {
    const double mag = std::stod(m[3].str());
    if (m[2].str() == "+" && mag != 0.0) {
      t.fail(key, fmt::format("\"{}\" has the wrong sign for ris's convention eps = eps' - j eps'' "
                              "(eps'' >= 0 for a lossy medium): write \"{:g} - {:g}j\"",
                              text, re_part, mag));
    }
    im_part = -mag;
  }
  if (re_part < 1.0) {
    t.fail(key, fmt::format("eps' = {:g} is below 1 (no natural ground has a relative "
                            "permittivity below that of vacuum)",
                            re_part));
  }
  return {re_part, im_part};
}

Fresnel fresnel_reflectivity(std::complex<double> eps, double incidence_rad) {
  return fresnel_reflectivity_cs(eps, std::cos(incidence_rad), std::sin(incidence_rad));
}

// |a / b|^2 as |a|^2 / |b|^2: the complex division (libgcc's __divdc3, with
// its C99 Annex G scaling and infinity checks) was a sixth of a LUT build;
// the quotient of norms differs from the norm of the quotient by rounding
// only (a few 1e-16 relative).
Fresnel fresnel_reflectivity_cs(std::complex<double> eps, double c, double s) {
  const std::complex<double> root = std::sqrt(eps - s * s);
  const double gh = std::norm(c - root) / std::norm(c + root);
  const double gv = std::norm(eps * c - root) / std::norm(eps * c + root);
  return {gh, gv};
}

}  // namespace ris::detail
