// Input texts shared by the tests: the small X-band SLAR most simulation
// tests fly, and backscatter libraries of constant-gamma categories (whose
// sigma0 = gamma cos(theta) a test can predict exactly).
//
// Example:
//   test::write_file(dir / "radar.toml", test::kSmallSlarRadar + "[film]\ngamma = 0.4\n");
//   test::write_file(dir / "library.toml",
//                    test::constant_gamma_library({{1, "grass", -12.0}, {2, "roof", -6.0}}));
#pragma once

#include <fmt/format.h>

#include <string>
#include <vector>

namespace ris::test {

// 9.4 GHz HH, 0.1 us pulse (15 m bins), 10 us sweep from 33.4 us, 5 mrad
// beam, track 3000 m up and 4000 m west of the scene heading north. The
// [track] table comes last, so tables may be appended ([film], ...).
inline const std::string kSmallSlarRadar = R"(
mode = "slar"
frequency = "9.4 GHz"
polarisation = "HH"
pulse_width = "0.1 us"
sweep_delay = "33.4 us"
sweep_length = "10 us"
azimuth_beamwidth = "5 mrad"
[track]
altitude = "3000 m"
near_edge_distance = "4000 m"
)";

struct ConstantGammaCategory {
  int id = 0;
  std::string name;
  double gamma_db = 0.0;
  std::string extra_model_keys;  // appended to [category.model] (e.g. valid_frequency)
};

// A library named `name` with one constant-gamma category per entry.
inline std::string constant_gamma_library(const std::vector<ConstantGammaCategory>& categories,
                                          const std::string& name = "test") {
  std::string s = fmt::format("[library]\nname = \"{}\"\n", name);
  for (const ConstantGammaCategory& c : categories) {
    s += fmt::format(
        "[[category]]\nid = {}\nname = \"{}\"\ncolour = \"#{:02x}a030\"\n[category.model]\n"
        "name = \"constant_gamma\"\ngamma_db = {}\n{}",
        c.id, c.name, (c.id * 48) % 256, c.gamma_db, c.extra_model_keys);
  }
  return s;
}

}  // namespace ris::test
