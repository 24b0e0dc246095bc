// The registry of dielectric models by name (the one table every list of
// their names reads), and their validity ranges (each model's file states its
// range and source).
#include "ris/backscatter/dielectric.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace ris {

namespace {

constexpr std::pair<std::string_view, DielectricModel> kDielectricModels[] = {
    {"dobson1985", DielectricModel::dobson1985},
    {"hallikainen1985", DielectricModel::hallikainen1985},
    {"mironov2009", DielectricModel::mironov2009},
};

constexpr std::pair<std::string_view, DobsonConductivity> kDobsonConductivities[] = {
    {"dobson1985", DobsonConductivity::dobson1985},
    {"peplinski1995", DobsonConductivity::peplinski1995},
};

template <typename E>
std::vector<std::string_view> names_of(std::span<const std::pair<std::string_view, E>> table) {
  std::vector<std::string_view> out;
  for (const auto& [name, value] : table) out.push_back(name);
  return out;
}

template <typename E>
std::optional<E> find_name(std::span<const std::pair<std::string_view, E>> table,
                           std::string_view name) {
  for (const auto& [n, value] : table)
    if (n == name) return value;
  return std::nullopt;
}

template <typename E>
std::string_view name_of(std::span<const std::pair<std::string_view, E>> table, E value) {
  for (const auto& [n, v] : table)
    if (v == value) return n;
  return "?";
}

}  // namespace

std::span<const std::pair<std::string_view, DielectricModel>> dielectric_model_registry() {
  return kDielectricModels;
}

std::vector<std::string_view> dielectric_model_names() {
  return names_of(dielectric_model_registry());
}

std::span<const std::pair<std::string_view, DobsonConductivity>> dobson_conductivity_registry() {
  return kDobsonConductivities;
}

std::vector<std::string_view> dobson_conductivity_names() {
  return names_of(dobson_conductivity_registry());
}

std::string joined_names(const std::vector<std::string_view>& names) {
  return fmt::format("{}", fmt::join(names, ", "));
}

std::optional<DielectricModel> parse_dielectric_model(std::string_view name) {
  return find_name(dielectric_model_registry(), name);
}

std::string_view to_string(DielectricModel m) {
  return name_of(dielectric_model_registry(), m);
}

std::optional<DobsonConductivity> parse_dobson_conductivity(std::string_view name) {
  return find_name(dobson_conductivity_registry(), name);
}

std::string_view to_string(DobsonConductivity c) {
  return name_of(dobson_conductivity_registry(), c);
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
