// Small hand-made inputs for SLAR tests: a sigma0 source with a closed form,
// tracks and radars that suit the small test scenes.
#pragma once

#include <cmath>
#include <cstdint>
#include <set>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/backscatter/sigma0_source.h"
#include "ris/scene/scene.h"
#include "ris/sensor/track.h"

namespace ris::test {

// sigma0 = gamma_c cos(theta) (Clapp's constant gamma), gamma_c = 0.05 (c + 1)
// for the categories in `have`.
class CosineSigma0Source : public Sigma0Source {
 public:
  explicit CosineSigma0Source(std::set<std::uint16_t> have = {0, 1, 2, 3, 4, 5})
      : have_(std::move(have)) {}
  bool has_category(std::uint16_t c) const override { return have_.count(c) > 0; }
  double sigma0(std::uint16_t c, double theta, const RadarBand&) const override {
    return gamma(c) * std::cos(theta);
  }
  std::string category_name(std::uint16_t c) const override { return "cat" + std::to_string(c); }
  std::string description() const override { return "test: gamma cos(theta)"; }
  static double gamma(std::uint16_t c) { return 0.05 * (c + 1); }

 private:
  std::set<std::uint16_t> have_;
};

inline Sigma0Lut cosine_lut(const Scene& s) {
  const std::set<std::uint16_t> used(s.category.begin(), s.category.end());
  const std::vector<std::uint16_t> cats(used.begin(), used.end());
  return Sigma0Lut::build(CosineSigma0Source(), RadarBand{8.6e9, Polarisation::HH}, cats,
                          "test-backscatter");
}

// Right-looking, heading north, the scene's west edge near_m from the track.
inline Track north_track(const Scene& s, double altitude_m, double near_m) {
  TrackSpec spec;
  spec.heading_rad = 0.0;
  spec.near_edge_ground_m = near_m;
  spec.altitude_m = altitude_m;
  return resolve_track(spec, s, "radar.toml");
}

}  // namespace ris::test
