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
#include "ris/perf/bench_setup.h"
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

// A 60 x 90 fractal scene of 10 m cells (categories 1-10) with a no-data
// hole, a no-data strip along its west edge and a 150 m tower, so that every
// look direction sees no data, shadow and layover: the fused and streamed
// SLAR paths are checked on it against the stage-by-stage reference.
inline Scene rugged_test_scene() {
  Scene s = make_bench_scene(60, 90, 10.0, 11);
  for (int r = 20; r < 26; ++r)
    for (int c = 40; c < 47; ++c) s.valid[s.index(r, c)] = 0;
  for (int r = 0; r < s.rows; ++r) s.valid[s.index(r, 0)] = 0;
  for (int r = 28; r < 33; ++r)
    for (int c = 60; c < 65; ++c) s.elevation_m[s.index(r, c)] = 150.0f;
  return s;
}

}  // namespace ris::test
