// Small hand-made inputs for SLAR tests: a sigma0 source with a closed form,
// tracks and radars that suit the small test scenes.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/backscatter/sigma0_source.h"
#include "ris/image/slar_image.h"
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

// Any two vectors of one type (std::vector or ris::UninitVector) hold the
// same bytes.
template <typename Vector>
bool same_bytes(const Vector& a, const Vector& b) {
  // Empty vectors may hold null data, which memcmp must not be given (UBSan).
  return a.size() == b.size() &&
         (a.empty() ||
          std::memcmp(a.data(), b.data(), a.size() * sizeof(typename Vector::value_type)) == 0);
}

// A straight track from the origin, length_m long at heading_rad (clockwise
// from north), altitude_m high.
inline Track endpoint_track(double heading_rad, double length_m, double altitude_m) {
  TrackSpec spec;
  spec.kind = TrackSpec::Kind::endpoints;
  spec.start_x_m = 0.0;
  spec.start_y_m = 0.0;
  spec.end_x_m = length_m * std::sin(heading_rad);
  spec.end_y_m = length_m * std::cos(heading_rad);
  spec.altitude_m = altitude_m;
  const Scene unused = Scene::flat(1, 1, 1.0, 0.0f, 0);
  return resolve_track(spec, unused, "radar.toml");
}

// A flat north-up grid of cell_m cells (category `category`) covering the
// track-frame rectangle s in [0, s_max_m], u in [u0_m, u1_m]; then
// fill(scene, cell index, s, u) at each cell centre's track coordinates, so
// that a scene built for a rotated track is the same terrain rotated.
template <typename Fill>
Scene track_frame_scene(const Track& t, double s_max_m, double u0_m, double u1_m, double cell_m,
                        std::uint16_t category, Fill fill) {
  double x_min = 1e30, x_max = -1e30, y_min = 1e30, y_max = -1e30;
  for (double s : {0.0, s_max_m}) {
    for (double u : {u0_m, u1_m}) {
      const auto [x, y] = t.world_from_along_cross(s, u);
      x_min = std::min(x_min, x);
      x_max = std::max(x_max, x);
      y_min = std::min(y_min, y);
      y_max = std::max(y_max, y);
    }
  }
  const int cols = static_cast<int>(std::round((x_max - x_min) / cell_m));
  const int rows = static_cast<int>(std::round((y_max - y_min) / cell_m));
  Scene scene = Scene::flat(rows, cols, cell_m, 0.0f, category);
  scene.origin_x_m = x_min;
  scene.origin_y_m = y_max;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const auto [x, y] = scene.cell_centre(r, c);
      const auto [s, u] = t.along_cross(x, y);
      fill(scene, scene.index(r, c), s, u);
    }
  }
  return scene;
}

// How two images of the same size agree, over their lines but the first and
// last margin_lines: the ratio of total powers (b / a), the sum of
// |a - b| relative to a's total (the pixel-wise error), and the fraction
// of pixels with the same mask.
struct ImageAgreement {
  double relative_total = 0.0, pixel_error = 0.0, same_mask = 0.0;
};

inline ImageAgreement image_agreement(const SlarImage& a, const SlarImage& b, int margin_lines) {
  double sum_a = 0, sum_b = 0, abs_diff = 0;
  int mask_same = 0, n = 0;
  for (int line = margin_lines; line < a.lines - margin_lines; ++line) {
    for (int bin = 0; bin < a.bins; ++bin) {
      const std::size_t i = a.index(line, bin);
      sum_a += a.mean_power_w[i];
      sum_b += b.mean_power_w[i];
      abs_diff += std::abs(double(a.mean_power_w[i]) - double(b.mean_power_w[i]));
      mask_same += a.mask[i] == b.mask[i] ? 1 : 0;
      ++n;
    }
  }
  return {sum_b / sum_a, abs_diff / sum_a, double(mask_same) / n};
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
