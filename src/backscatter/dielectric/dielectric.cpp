// The table of dielectric models by name, and their validity ranges (each
// model's file states its range and source).
#include "ris/backscatter/dielectric.h"

#include <fmt/format.h>

namespace ris {

std::optional<DielectricModel> parse_dielectric_model(std::string_view name) {
  if (name == "dobson1985") return DielectricModel::dobson1985;
  if (name == "hallikainen1985") return DielectricModel::hallikainen1985;
  if (name == "mironov2009") return DielectricModel::mironov2009;
  return std::nullopt;
}

std::string_view to_string(DielectricModel m) {
  switch (m) {
    case DielectricModel::dobson1985:
      return "dobson1985";
    case DielectricModel::hallikainen1985:
      return "hallikainen1985";
    case DielectricModel::mironov2009:
      return "mironov2009";
  }
  return "?";
}

std::optional<DobsonConductivity> parse_dobson_conductivity(std::string_view name) {
  if (name == "dobson1985") return DobsonConductivity::dobson1985;
  if (name == "peplinski1995") return DobsonConductivity::peplinski1995;
  return std::nullopt;
}

std::string_view to_string(DobsonConductivity c) {
  return c == DobsonConductivity::dobson1985 ? "dobson1985" : "peplinski1995";
}

std::complex<double> soil_permittivity(DielectricModel m, const SoilComposition& soil,
                                       double frequency_hz) {
  switch (m) {
    case DielectricModel::dobson1985:
      return dobson1985_permittivity(soil, frequency_hz);
    case DielectricModel::hallikainen1985:
      return hallikainen1985_permittivity(soil, frequency_hz);
    case DielectricModel::mironov2009:
      return mironov2009_permittivity(soil, frequency_hz);
  }
  return {1.0, 0.0};
}

namespace {
void check(std::vector<std::string>& out, const char* what, double v, double lo, double hi,
           const char* unit) {
  if (v < lo || v > hi) {
    out.push_back(fmt::format("{} = {:g}{} is outside the validity range [{:g}, {:g}]{}", what, v,
                              unit, lo, hi, unit));
  }
}
}  // namespace

std::vector<std::string> dielectric_validity(DielectricModel m, const SoilComposition& soil,
                                             double frequency_hz) {
  std::vector<std::string> out;
  const double f_ghz = frequency_hz / 1e9;
  switch (m) {
    case DielectricModel::dobson1985:
      // Dobson et al. (1985): fitted to the 1.4-18 GHz measurements of
      // Hallikainen et al. (1985), five soils, mv up to about 0.5.
      check(out, "frequency", f_ghz, 1.4, 18.0, " GHz");
      check(out, "moisture", soil.moisture_m3_m3, 0.0, 0.5, " m3/m3");
      check(out, "bulk_density", soil.bulk_density_g_cm3, 1.0, 2.0, " g/cm3");
      check(out, "temperature", soil.temperature_c, 0.0, 40.0, " C");
      break;
    case DielectricModel::hallikainen1985:
      // Hallikainen et al. (1985) Table V: fits at 1.4-18 GHz, five soils with
      // sand 5.0-51.5 % and clay 13.4-47.4 %, mv up to about 0.5.
      check(out, "frequency", f_ghz, 1.4, 18.0, " GHz");
      check(out, "moisture", soil.moisture_m3_m3, 0.0, 0.5, " m3/m3");
      check(out, "sand", soil.sand_fraction, 0.05, 0.515, "");
      check(out, "clay", soil.clay_fraction, 0.134, 0.474, "");
      break;
    case DielectricModel::mironov2009:
      // Mironov, Kosolapova & Fomin (2009): fitted to 0.045-26.5 GHz data for
      // soils with 0-76 % clay, at room temperature.
      check(out, "frequency", f_ghz, 0.045, 26.5, " GHz");
      check(out, "moisture", soil.moisture_m3_m3, 0.0, 0.5, " m3/m3");
      check(out, "clay", soil.clay_fraction, 0.0, 0.76, "");
      break;
  }
  return out;
}

}  // namespace ris
