#include "backscatter/models/soil_permittivity.h"

#include "backscatter/models/model_util.h"
#include "ris/util/error.h"

namespace ris::detail {

std::complex<double> SoilPermittivity::at(double frequency_hz) const {
  if (!model_) return fixed_;
  return soil_permittivity(*model_, soil_, frequency_hz);
}

void SoilPermittivity::check_band(double frequency_hz) const {
  if (!model_) return;
  for (const std::string& problem : dielectric_validity(*model_, soil_, frequency_hz)) {
    report_out_of_validity(ctx_, key_, std::string(to_string(*model_)) + ": " + problem);
  }
}

std::string SoilPermittivity::describe() const {
  if (!model_) return fmt::format("{:g} - {:g}j", fixed_.real(), -fixed_.imag());
  if (*model_ == DielectricModel::mironov2009) {
    return fmt::format("{} (mv = {:g}, clay = {:g})", to_string(*model_), soil_.moisture_m3_m3,
                       soil_.clay_fraction);
  }
  if (*model_ == DielectricModel::dobson1985 &&
      soil_.conductivity != DobsonConductivity::dobson1985) {
    return fmt::format("{} (mv = {:g}, clay = {:g}, sand = {:g}, conductivity {})",
                       to_string(*model_), soil_.moisture_m3_m3, soil_.clay_fraction,
                       soil_.sand_fraction, to_string(soil_.conductivity));
  }
  return fmt::format("{} (mv = {:g}, clay = {:g}, sand = {:g})", to_string(*model_),
                     soil_.moisture_m3_m3, soil_.clay_fraction, soil_.sand_fraction);
}

SoilPermittivity read_soil_permittivity(ConfigTable& params, const std::string& key,
                                        const ModelContext& ctx) {
  const toml::node* node = params.raw(key);
  if (node == nullptr) params.fail(key, "missing required key (\"15 - 4j\" or a dielectric table)");
  if (const auto* s = node->as_string()) {
    return SoilPermittivity(parse_permittivity(params, key, s->get()));
  }
  std::optional<ConfigTable> t = params.subtable(key);
  if (!t) params.fail(key, "expected \"eps' - eps''j\" (e.g. \"15 - 4j\") or a dielectric table");
  const DielectricModel model = t->get_registered_enum("model", dielectric_model_registry());
  SoilComposition soil;
  soil.moisture_m3_m3 = t->get_double("moisture");
  soil.clay_fraction = t->get_double("clay");
  // Mironov 2009 depends on clay only: sand is optional there (accepted and
  // checked, so a library can state its soil's texture, but never used).
  const bool needs_sand = model != DielectricModel::mironov2009;
  soil.sand_fraction = needs_sand ? t->get_double("sand") : t->get_double_or("sand", 0.0);
  if (!(soil.moisture_m3_m3 >= 0.0 && soil.moisture_m3_m3 <= 1.0)) {
    t->fail("moisture", "expected a volumetric water content in [0, 1] m3/m3");
  }
  if (!(soil.clay_fraction >= 0.0 && soil.clay_fraction <= 1.0)) {
    t->fail("clay", "expected a mass fraction in [0, 1]");
  }
  if (!(soil.sand_fraction >= 0.0 && soil.sand_fraction <= 1.0)) {
    t->fail("sand", "expected a mass fraction in [0, 1]");
  }
  if (soil.clay_fraction + soil.sand_fraction > 1.0 + 1e-9) {
    t->fail("sand", "clay + sand exceeds 1 (they are mass fractions of the same soil)");
  }
  if (model == DielectricModel::dobson1985) {
    soil.bulk_density_g_cm3 = t->get_double_or("bulk_density", soil.bulk_density_g_cm3);
    soil.temperature_c = t->get_double_or("temperature", soil.temperature_c);
    soil.conductivity = t->get_registered_enum_or("conductivity", dobson_conductivity_registry(),
                                                  DobsonConductivity::dobson1985);
    if (!(soil.bulk_density_g_cm3 > 0.0 && soil.bulk_density_g_cm3 < 2.66)) {
      t->fail("bulk_density", "expected a dry bulk density in (0, 2.66) g/cm3");
    }
  }
  t->finish();
  return SoilPermittivity(model, soil, ctx, params.key_path(key));
}

}  // namespace ris::detail
