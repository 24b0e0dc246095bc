// Internal: the PPI's line sources (sim/engine/slar_line_engine.h): one ray
// from the site per line, its terrain and look geometry straight into the
// engine's scratch (ppi_ray_geometry, as compute_ppi_geometry fills a ray).
//  - PolarSource: the whole scene in memory (simulate_ppi);
//  - WindowedPolarSource: a streamed block of rays whose terrain was sampled
//    beforehand from scene windows (ris/sim/ppi_stream.h), in the whole
//    scene's grid coordinates, so every sample takes the in-memory cells and
//    weights and the engine gives the in-memory run's rows.
// Both compute the look geometry themselves (kMakesGeometry) and write no
// scene maps.
#pragma once

#include <cstdint>
#include <utility>
#include <variant>
#include <vector>

#include "ris/geometry/ppi_geometry.h"
#include "ris/geometry/terrain_line.h"
#include "ris/scene/scene.h"
#include "sim/engine/slar_line_engine.h"

namespace ris::detail {

// The ray's outputs in the engine's scratch.
inline PpiRayOut ray_out_in(LineScratch& s) {
  return PpiRayOut{s.height.data(), s.range.data(),    s.incidence.data(), s.local_incidence.data(),
                   s.area.data(),   s.near_end.data(), s.far_end.data(),   s.category.data(),
                   s.flags.data(),  s.dh_du.data()};
}

struct PolarSource {
  static constexpr bool kMakesGeometry = true;
  const Scene& scene;
  const TerrainTexels& tex;
  const PpiGeometry& pg;
  PpiRayScratch& ray;

  LineSpan load(int line, LineScratch& s) {
    ppi_ray_geometry(scene, tex, pg, line, ray_out_in(s), ray);
    return {0, pg.rays.samples, &pg.rays};
  }
  void store_maps(int, const LineSpan&, const LineScratch&) const {}
  void finish_block() const {}
};

struct PolarThreadSource {
  const Scene& scene;
  const TerrainTexels& tex;
  const PpiGeometry& pg;
  PpiRayScratch ray;
  std::variant<PolarSource> block(int, int) { return PolarSource{scene, tex, pg, ray}; }
};

// A streamed block's rays [k0, k0 + n): ray k's samples [span[k - k0]) were
// sampled into the terrain arrays' row k - k0 (pg.rays.samples a row).
struct SampledRays {
  const PpiGeometry& pg;
  int k0 = 0;
  const std::vector<std::pair<int, int>>& span;
  // SampledTerrain's types (the sampler's output; read here only).
  float* height_m;
  float* dz_dx;
  float* dz_dy;
  std::uint16_t* category;
  std::uint8_t* flags;
};

struct WindowedPolarSource {
  static constexpr bool kMakesGeometry = true;
  const SampledRays& rays;

  LineSpan load(int line, LineScratch& s) const {
    const int k = line - rays.k0, samples = rays.pg.rays.samples;
    const auto [begin, end] = rays.span[static_cast<std::size_t>(k)];
    const std::size_t at = static_cast<std::size_t>(k) * static_cast<std::size_t>(samples);
    const SampledTerrain terrain{rays.height_m + at, rays.dz_dx + at, rays.dz_dy + at,
                                 rays.category + at, rays.flags + at};
    ppi_ray_geometry_from_terrain(rays.pg, line, begin, end, terrain, ray_out_in(s));
    return {0, samples, &rays.pg.rays};
  }
  void store_maps(int, const LineSpan&, const LineScratch&) const {}
  void finish_block() const {}
};

struct WindowedPolarThreadSource {
  const SampledRays& rays;
  std::variant<WindowedPolarSource> block(int, int) const { return WindowedPolarSource{rays}; }
};

}  // namespace ris::detail
