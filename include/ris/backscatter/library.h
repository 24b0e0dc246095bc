// A category library: for each backscatter category of a scene, a name, a
// display colour and the model that gives its sigma0 (optionally a different
// model per band or polarisation). The simulation reads it through
// Sigma0Source; load_sigma0_source() also accepts a CSV table file.
//
// Library format (TOML; docs/backscatter.md has every key):
//   [library]
//   name = "ku-geometric"
//   description = "..."
//   allow_extrapolation = false     # optional; per category too
//
//   [[category]]
//   id = 4
//   name = "short corn"
//   colour = "#e0c040"
//   [category.model]                # default model for every band
//   name = "water_cloud"
//   ...
//   [[category.band]]               # optional overrides, first match wins
//   frequency = ["8 GHz", "9 GHz"]  # inclusive range; optional
//   polarisation = ["HH", "VV"]     # optional
//   [category.band.model]
//   name = "table"
//   file = "ku-geometric-8.6GHz.csv"
//
// Example:
//   std::unique_ptr<ris::Sigma0Source> src =
//       ris::load_sigma0_source("data/backscatter/ku-geometric.toml");
//   double s0 = src->sigma0(4, ris::deg_to_rad(30.0), {8.6e9, ris::Polarisation::HH});
#pragma once

#include <memory>
#include <string>

#include "ris/backscatter/sigma0_source.h"

namespace ris {

// Loads a category library (.toml) or a sigma0 table (.csv). Every model is
// built and its parameters checked here (unknown model, missing or extra
// keys, values outside a model's validity: InputError naming the file and
// key); band-dependent validity (e.g. ks) is checked on the first sigma0()
// call for each category and band.
std::unique_ptr<Sigma0Source> load_sigma0_source(const std::string& path);

// The same, with every model of a library (.toml) allowed outside its
// validity (as if each said allow_extrapolation = true; a warning per
// category and band instead of a refusal): `ris serve`'s switch for the
// message that asks for it. A .csv table has no validity to lift.
std::unique_ptr<Sigma0Source> load_sigma0_source(const std::string& path,
                                                 bool force_allow_extrapolation);

// The library the simulation uses when none is given:
// <data>/backscatter/ku-geometric.toml.
std::string default_sigma0_library_path();

}  // namespace ris
