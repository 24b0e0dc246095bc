// Internal: point targets (ris/sim/point_target.h) on a PPI's rays, shared by
// the in-memory run (simulate_ppi: src/sim/modes/ppi_simulation.cpp) and the
// streamed one (ris/sim/ppi_stream.h), so both place, find and report them
// with the same code (the same bytes).
//
//   - ray_candidates places each target on every (padded) ray whose sector
//     holds its azimuth, in front of the site, before the rays are formed;
//   - the line engine (or the streamed block) finds each candidate lit or
//     hidden as its ray is formed (the scene-query stage PointTargetQuery,
//     sim/engine/scene_query.h) and adds its power;
//   - fold_ray_targets gives the returns seen (in target and ray order),
//     their powers and the names of the targets seen on no ray.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ris/geometry/ppi_geometry.h"
#include "ris/sim/point_target.h"

namespace ris::detail {

// Whether azimuth alpha (rad, clockwise from north) is in ray k's sector
// [centre - spacing / 2, centre + spacing / 2).
bool azimuth_on_ray(const PpiGeometry& pg, int k, double alpha);

// The targets on every (padded) ray whose sector holds their azimuth, in
// front of the site (point_returns_on_rays's rule before the shadow test):
// one candidate per target and ray, `target` the candidate's own index;
// target_of[c] the target of candidate c. base_m[t]: the terrain height
// under target t (terrain_height_at).
std::vector<PointCandidate> ray_candidates(const std::vector<PointTarget>& targets,
                                           const std::vector<double>& base_m, const PpiGeometry& pg,
                                           std::vector<std::size_t>& target_of);

// The candidates' results (lit[c], power_w[c] for candidate c) folded as the
// in-memory run does: the returns seen, in target and ray order, with their
// power; a target seen on no ray is hidden (its name appended).
void fold_ray_targets(const std::vector<PointTarget>& targets,
                      const std::vector<PointCandidate>& candidates,
                      const std::vector<std::size_t>& target_of,
                      const std::vector<std::uint8_t>& lit, const std::vector<double>& power_w,
                      std::vector<PointReturn>& returns, std::vector<double>& point_power_w,
                      std::vector<std::string>& hidden);

}  // namespace ris::detail
