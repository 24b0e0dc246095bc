// The terrain along a straight ground line sampled at equal steps: SLAR/SAR
// zero-Doppler lines off the grid axes (stage path and fused path alike) and
// PPI rays (MODEL.md section 2, "Tracks that are not along a grid axis":
// bilinear elevation and slope, the nearest cell's category, at a step no
// larger than half a cell).
//
// Along a line the grid position advances by a constant step, so sample j
// sits at (col0 + j dcol, row0 + j drow); the samples within the scene are
// one interval [begin, end), found once per line (inside_samples), and only
// those are sampled. The sampler reads one 16-byte texel per corner cell
// (height, dz/dx, dz/dy, category; TerrainTexels) instead of four rasters,
// and weights it as one 4-float vector: the bilinear rule and its weights
// are ris/geometry/terrain_sample.h's bilinear_footprint.
//
// Example (one SLAR line of g.samples samples at along-track position s_m):
//   const ris::TerrainTexels tex = ris::terrain_texels(scene);
//   const auto [x0, y0] = track.world_from_along_cross(s_m, 0.0);
//   const ris::GridLine line = ris::grid_line(scene, x0, y0, track.cross_x, track.cross_y,
//                                             g.first_sample_u_m, g.sample_step_m);
//   const auto [begin, end] = ris::inside_samples(line, scene.rows, scene.cols, g.samples);
//   ris::sample_terrain_line(tex, line, begin, end, {height, dz_dx, dz_dy, category, flags});
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>

#include "ris/geometry/line_scan.h"  // sample_flag
#include "ris/scene/scene.h"

namespace ris {

// One cell's terrain as the line sampler reads it: height (NaN where the cell
// has no data), the slope of ris/geometry/surface_gradient.h (NaN where no
// data) and the category (exact as a float up to 2^24). Trivial (no
// initialisers), so that a scene's texels are written once, not zeroed first.
struct alignas(16) TerrainTexel {
  float height_m;
  float dz_dx;
  float dz_dy;
  float category;
};

// TerrainTexels' deleter: keeps the largest freed array for the next run
// (terrain_line.cpp). bytes: the array's allocated size.
struct TerrainTexelsFree {
  std::size_t bytes = 0;
  void operator()(TerrainTexel* p) const;
};

struct TerrainTexels {
  int rows = 0, cols = 0;
  std::unique_ptr<TerrainTexel[], TerrainTexelsFree> texel;  // rows * cols, Scene::index order
  std::size_t size() const {
    return static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols);
  }
};

// Which code the texels and the sampler run: the widest the CPU has (AVX-512
// kernels, kernels/simd/avx512.h, where it has them), or the portable one
// whatever the CPU (for tests: both give the same bytes).
enum class SamplerKernel { best, portable };

// The texels of a whole scene (16 bytes a cell), in parallel over rows; each
// row's interior in one vectorised pass. The array asks for transparent huge
// pages (Linux), and the largest freed one is kept for the next run: a 2000 x
// 2000 scene's 64 MB would otherwise be 16,000 page faults on every run.
TerrainTexels terrain_texels(const Scene& scene, SamplerKernel kernel = SamplerKernel::best);

// A straight line of samples in grid coordinates (Scene::grid_from_world:
// col east, row south, cell centres at integer + 1/2).
struct GridLine {
  double col0 = 0.0, row0 = 0.0;  // sample 0
  double dcol = 0.0, drow = 0.0;  // per sample
  double col(int j) const { return col0 + j * dcol; }
  double row(int j) const { return row0 + j * drow; }
  // Within the scene rectangle (edges included), the rule of
  // bilinear_terrain_sample.
  bool inside(int j, int rows, int cols) const {
    const double c = col(j), r = row(j);
    return c >= 0.0 && c <= cols && r >= 0.0 && r <= rows;
  }
};

// The line from world point (x0_m, y0_m) along the unit ground direction
// (dir_x, dir_y), sample j at distance first_u_m + j step_m.
GridLine grid_line(const Scene& scene, double x0_m, double y0_m, double dir_x, double dir_y,
                   double first_u_m, double step_m);

// The samples of [0, samples) within the scene: exactly those where
// GridLine::inside holds, one interval (the position is monotone in j),
// found by bisection. begin == end when none.
std::pair<int, int> inside_samples(const GridLine& line, int rows, int cols, int samples);

// sample_terrain_line's outputs, out[j - begin] for sample j.
struct SampledTerrain {
  float* height_m;          // NaN where no data
  float* dz_dx;             // NaN where no data
  float* dz_dy;             // NaN where no data
  std::uint16_t* category;  // 0 where no data
  std::uint8_t* flags;      // sample_flag::kNoData where the sample touches a no-data cell, else 0
};

// Bilinear height and slope and the nearest cell's category for samples
// [begin, end), all inside the scene (inside_samples).
void sample_terrain_line(const TerrainTexels& tex, const GridLine& line, int begin, int end,
                         const SampledTerrain& out, SamplerKernel kernel = SamplerKernel::best);

}  // namespace ris
