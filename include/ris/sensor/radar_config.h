// Reading a radar description file (TOML, docs/radar-format.md) into a checked
// RadarParams: the one place where radar text becomes numbers (DESIGN.md
// principle 2). Every key is read through ConfigTable, so an unknown or
// misspelled key is an error; every value is checked (positive pulse width and
// beamwidth, near range before far range, a known polarisation, ...) and a bad
// one throws InputError naming the file and the key.
//
// Example:
//   ris::RadarParams radar = ris::load_radar("data/radars/seed-fig4-5.toml");
//   double lambda_m = radar.wavelength_m();            // 0.0349 m at 8.6 GHz
//   int bins = radar.range_bins;                        // 241
#pragma once

#include <string>

#include <toml++/toml.h>

#include "ris/sensor/radar_params.h"

namespace ris {

// Parses and checks the radar file at `path`. Keys left out take the defaults
// documented in docs/radar-format.md; the reference cell's factors are filled
// in (mid-swath values of this radar) so that RadarParams is complete.
RadarParams load_radar(const std::string& path);

// The same from an already-parsed document; `source_file` names it in errors.
RadarParams radar_from_toml(const toml::table& doc, const std::string& source_file);

}  // namespace ris
