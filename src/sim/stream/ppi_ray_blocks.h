// Internal: pass 1's computing half of a streamed PPI (any rank): block b's
// rays, their terrain sampled from windows of the scene file (range segment
// by segment; within one, groups of consecutive rays whose cells fit a
// window: sim/engine/texel_window.h), then through the line engine with the
// windowed polar source (sim/sources/polar_lines.h), with the point targets
// on the block's rays (sim/targets/ppi_ray_targets.h). Its block travels to
// rank 0 (ppi_rays_pass.h) packed as RayBlock.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "kernels/image/slar_element.h"
#include "ris/geometry/ppi_geometry.h"
#include "ris/geometry/terrain_line.h"
#include "ris/image/slar_image.h"
#include "ris/scene/scene_stream.h"
#include "ris/sim/point_target.h"
#include "ris/sim/radiometry_setup.h"
#include "sim/engine/slar_line_engine.h"
#include "sim/engine/texel_window.h"
#include "sim/stream/slar_stream_targets.h"

namespace ris::detail {

// A block's counts of pass 1 (summed over the blocks; r_min and r_max: the
// slant range of the samples seen, for the swath-misses-the-scene message).
struct RayCounts {
  std::int64_t in_swath = 0, shadow = 0, layover = 0, back_facing = 0, nodata = 0;
  std::int64_t windows = 0, max_window_cells = 0;  // scene windows read
  float r_min = std::numeric_limits<float>::infinity();
  float r_max = -std::numeric_limits<float>::infinity();
  void add(const RayCounts& o) {
    in_swath += o.in_swath;
    shadow += o.shadow;
    layover += o.layover;
    back_facing += o.back_facing;
    nodata += o.nodata;
    windows += o.windows;
    max_window_cells = std::max(max_window_cells, o.max_window_cells);
    r_min = std::min(r_min, o.r_min);
    r_max = std::max(r_max, o.r_max);
  }
};

// A block of rays as computed by any rank of an MPI run and consumed, in
// ray order, by rank 0 (src/sim/engine/block_schedule.h): its range profiles,
// counts and its point targets' results (src/sim/targets/ppi_ray_targets.h).
struct RayBlock {
  int k0 = 0, k1 = 0;
  SlarLineProfiles prof;
  RayCounts counts;
  BlockTargets targets;
};

void pack_ray_block(const RayBlock& k, std::vector<char>& out);
RayBlock unpack_ray_block(const char* p, std::size_t n);

// How a block's rays are read and run (PpiStreamRun::set_up).
struct PpiRayLayout {
  int block_rays = 1;
  int segment_samples = 2048;     // range samples a window covers at most
  std::int64_t window_cells = 0;  // cells a window holds at most
  int fail_block = -1;            // FaultPlan::line_block
};

class PpiRayBlocks {
 public:
  // candidates: the point targets on the padded rays (ray_candidates);
  // spare: consumed blocks whose buffers a new block reuses (the pass's).
  PpiRayBlocks(const SceneStreamReader& in, const PpiGeometry& pg, const RadiometrySetup& rs,
               const std::string& radar_file, int bins, const PpiRayLayout& layout,
               const std::vector<PointCandidate>& candidates, std::vector<RayBlock>& spare);

  int blocks() const;
  RayBlock compute(int b);

 private:
  std::optional<LinePointTargets> candidates_on_rays(int k0, int k1) const;
  void sample_block_terrain(int k0, int k1);
  CellBox ray_cells(int k, int a, int b) const;
  std::int64_t padded_cells(const CellBox& c) const { return padded_box(c, grid()).cells(); }
  void sample_group(int g0, int g1, int a, int b, const CellBox& cells);
  void block_profiles(int k0, int k1, SlarLineProfiles& prof, RayCounts& counts,
                      LinePointTargets* targets);
  const Scene& grid() const { return in_.grid(); }
  const PpiGeometry& pg() const { return pg_; }
  int all_rays() const { return pg_.rays.lines; }
  int bins() const { return bins_; }

  const SceneStreamReader& in_;
  const PpiGeometry& pg_;
  const RadiometrySetup& rs_;
  const int bins_;
  const PpiRayLayout layout_;
  const std::vector<PointCandidate>& candidates_;
  std::vector<RayBlock>& spare_;
  const TwoWayGainTable gain2_;
  const SlarElementContext ctx_;  // reads gain2_
  // The block's rays and their sampled terrain.
  std::vector<GridLine> lines_;
  std::vector<std::pair<int, int>> span_;  // inside_samples per ray
  std::vector<float> t_height_, t_dzdx_, t_dzdy_;
  std::vector<std::uint16_t> t_cat_;
  std::vector<std::uint8_t> t_flags_;
  Scene ws_;                           // the window
  RayCounts* block_counts_ = nullptr;  // the block being computed
};

}  // namespace ris::detail
