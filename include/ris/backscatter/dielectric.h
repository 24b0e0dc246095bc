// Soil permittivity from moisture, texture and frequency: the dielectric
// models a bare-soil backscatter model can take its permittivity from.
// Convention (everywhere in ris): eps = eps' - j eps'', eps'' >= 0, returned
// as std::complex(eps', -eps'').
//
// One file per model under src/backscatter/dielectric/ with its source and
// validity range at the top: dobson1985, hallikainen1985, mironov2009.
//
// Example:
//   ris::SoilComposition soil{0.20, 0.20, 0.40};   // mv, clay, sand
//   std::complex<double> eps =
//       ris::soil_permittivity(ris::DielectricModel::dobson1985, soil, 5.3e9);
#pragma once

#include <complex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ris {

enum class DielectricModel { dobson1985, hallikainen1985, mironov2009 };

// The effective conductivity fit in Dobson 1985's free-water loss term
// (src/backscatter/dielectric/dobson1985.cpp): Dobson et al.'s own, fitted at
// 1.4-18 GHz, or Peplinski, Ulaby & Dobson's (1995), fitted at 0.3-1.3 GHz and
// used at every band by several radiative-transfer codes (HUT, DMRT-ML). They
// differ by 10-70 % in eps''.
enum class DobsonConductivity { dobson1985, peplinski1995 };

struct SoilComposition {
  double moisture_m3_m3 = 0.2;      // volumetric water content mv
  double clay_fraction = 0.2;       // mass fraction of clay, 0..1
  double sand_fraction = 0.4;       // mass fraction of sand, 0..1
  double bulk_density_g_cm3 = 1.5;  // dry bulk density rho_b (Dobson only)
  double temperature_c = 20.0;      // soil temperature (Dobson only)
  DobsonConductivity conductivity = DobsonConductivity::dobson1985;  // (Dobson only)
};

// The one registry of the dielectric models' names, in the order they are
// listed: the radar/library TOML key `model`, `ris dielectric --model`, its
// "all", and Python's ris.DIELECTRIC_MODELS all read it. A new model is a
// file under src/backscatter/dielectric/, an enum value and a line here.
std::span<const std::pair<std::string_view, DielectricModel>> dielectric_model_registry();
// The registry's names: "dobson1985", "hallikainen1985", "mironov2009".
std::vector<std::string_view> dielectric_model_names();
// The same for Dobson 1985's conductivity fits.
std::span<const std::pair<std::string_view, DobsonConductivity>> dobson_conductivity_registry();
std::vector<std::string_view> dobson_conductivity_names();
// Names joined for a message or a help text: "dobson1985, hallikainen1985, mironov2009".
std::string joined_names(const std::vector<std::string_view>& names);

// A name of the registry (exact, as listed); nullopt otherwise.
std::optional<DielectricModel> parse_dielectric_model(std::string_view name);
std::string_view to_string(DielectricModel m);
std::optional<DobsonConductivity> parse_dobson_conductivity(std::string_view name);
std::string_view to_string(DobsonConductivity c);

// The complex relative permittivity (eps' - j eps'') of the soil at frequency_hz.
std::complex<double> soil_permittivity(DielectricModel m, const SoilComposition& soil,
                                       double frequency_hz);

// Where the inputs fall outside the model's validity range: one message per
// problem, naming the input and the range; empty when valid.
std::vector<std::string> dielectric_validity(DielectricModel m, const SoilComposition& soil,
                                             double frequency_hz);

// The models themselves (src/backscatter/dielectric/*.cpp).
std::complex<double> dobson1985_permittivity(const SoilComposition& soil, double frequency_hz);
std::complex<double> hallikainen1985_permittivity(const SoilComposition& soil, double frequency_hz);
std::complex<double> mironov2009_permittivity(const SoilComposition& soil, double frequency_hz);

}  // namespace ris
