// A study description file (data/studies/*.toml, docs/study.md): the inputs
// and the comparison window of a `ris study` run, so that a published
// study (the seed's figure 7) can be shipped and re-run as it stands.
//
//   [study]
//   name = "seed figure 7"
//   scene = "../scenes/ku-geometric.toml"       # relative to this file
//   radar = "../radars/seed-fig7.toml"
//   backscatter = "../backscatter/ku-geometric.toml"   # optional
//   bands = "1.25 GHz:HH, 8.6 GHz:HH, 8.6 GHz:VV"      # optional
//   seed = 1                                   # optional
//   range_fraction = [0.33333333, 0.66666667]  # optional, of the swath
//   incidence_bin = "1 deg"                    # optional
//
// Unknown keys, a missing [study] table, bad fractions (not 0 <= lo < hi <= 1)
// or a non-positive bin are InputErrors naming the file and key.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ris/analysis/study_separability.h"

namespace ris {

struct StudyConfig {
  std::string file;
  std::string name;
  std::optional<std::string> scene, radar, backscatter;  // resolved paths
  std::optional<std::string> bands;                      // "F:P, F:P, ..."
  std::optional<std::uint64_t> seed;
  std::optional<double> range_lo_fraction, range_hi_fraction;
  std::optional<double> incidence_bin_rad;
};

StudyConfig read_study_config(const std::string& path);

// Checks a window given on the command line or in a file (key names it).
void check_study_window(const StudyWindow& window, const std::string& file, const std::string& key);

}  // namespace ris
