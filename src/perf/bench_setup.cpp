#include "ris/perf/bench_setup.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ris/util/counter_rng.h"

namespace ris {

namespace {

// Lattice value in [-1, 1] keyed by (seed, octave, lattice point).
float lattice(std::uint64_t seed, std::uint32_t octave, std::uint32_t i, std::uint32_t j) {
  const Philox4x32Block b =
      philox4x32_10({i, j, octave, 0x42454E43u},  // "BENC"
                    {static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)});
  return static_cast<float>(b[0]) * (2.0f / 4294967296.0f) - 1.0f;
}

// fBm at fractional lattice position (x, y) in units of the coarsest period.
struct Fbm {
  std::uint64_t seed;
  int octaves;
  float operator()(double x, double y, std::uint32_t salt) const {
    float sum = 0.0f, amp = 1.0f, norm = 0.0f;
    for (int o = 0; o < octaves; ++o) {
      const double fx = std::floor(x), fy = std::floor(y);
      const auto i = static_cast<std::uint32_t>(static_cast<std::int64_t>(fx));
      const auto j = static_cast<std::uint32_t>(static_cast<std::int64_t>(fy));
      const float tx = static_cast<float>(x - fx), ty = static_cast<float>(y - fy);
      // Smoothstep weights so the surface has continuous slope.
      const float sx = tx * tx * (3.0f - 2.0f * tx), sy = ty * ty * (3.0f - 2.0f * ty);
      const std::uint32_t oc = static_cast<std::uint32_t>(o) + salt;
      const float v00 = lattice(seed, oc, i, j), v10 = lattice(seed, oc, i + 1, j);
      const float v01 = lattice(seed, oc, i, j + 1), v11 = lattice(seed, oc, i + 1, j + 1);
      sum += amp * ((v00 * (1 - sx) + v10 * sx) * (1 - sy) + (v01 * (1 - sx) + v11 * sx) * sy);
      norm += amp;
      amp *= 0.5f;
      x *= 2.0;
      y *= 2.0;
    }
    return sum / norm;  // in [-1, 1]
  }
};

}  // namespace

Scene make_bench_scene(int rows, int cols, double cell_m, std::uint64_t seed) {
  Scene s;
  s.rows = rows;
  s.cols = cols;
  s.dx_m = s.dy_m = cell_m;
  s.origin_x_m = 0.0;
  s.origin_y_m = rows * cell_m;
  s.elevation_m.resize(s.size());
  s.category.resize(s.size());
  s.valid.assign(s.size(), 1);
  const double side_m = std::min(rows, cols) * cell_m;
  const double period_m = side_m / 4.0;  // coarsest features: a quarter of the scene
  const float relief_m = static_cast<float>(0.05 * side_m);
  // Octaves down to about two cells.
  const int octaves = std::max(1, static_cast<int>(std::log2(period_m / (2.0 * cell_m))));
  const Fbm height{seed, octaves};
  const Fbm patches{seed, 3};
#pragma omp parallel for schedule(dynamic, 16)
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      const double x = (c + 0.5) * cell_m / period_m, y = (r + 0.5) * cell_m / period_m;
      const float h = height(x, y, 0);
      const std::size_t i = s.index(r, c);
      s.elevation_m[i] = std::max(0.0f, 0.5f * relief_m * (h + 1.0f));
      const float p = patches(4.0 * x, 4.0 * y, 1000);
      const int cat = static_cast<int>(std::floor((h + 1.0f) * 3.0f + 4.0f * p + 5.0f));
      s.category[i] = static_cast<std::uint16_t>(std::clamp(cat, 1, 10));
    }
  }
  return s;
}

RadarParams bench_radar(RadarParams radar, const Scene& scene, double heading_rad) {
  const double H = radar.track.altitude_m;
  radar.track.kind = TrackSpec::Kind::heading_near_edge;
  radar.track.heading_rad = heading_rad;
  const double near_u = radar.track.near_edge_ground_m;
  // The scene's extent across a track with this heading (look direction
  // (cos h, -sin h) or its opposite).
  const double width_m = scene.cols * scene.dx_m * std::abs(std::cos(heading_rad)) +
                         scene.rows * scene.dy_m * std::abs(std::sin(heading_rad));
  float h_max = 0.0f;
  for (float h : scene.elevation_m) h_max = std::max(h_max, h);
  const double near_r = std::hypot(near_u, H - double(h_max)) - 2.0 * radar.range_bin_m;
  const double far_r = std::hypot(near_u + width_m, H) + 2.0 * radar.range_bin_m;
  radar.near_slant_range_m = near_r;
  radar.range_bins = static_cast<int>(std::ceil((far_r - near_r) / radar.range_bin_m));
  radar.far_slant_range_m = near_r + radar.range_bins * radar.range_bin_m;
  return radar;
}

}  // namespace ris
