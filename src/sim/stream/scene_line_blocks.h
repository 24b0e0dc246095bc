// Internal: pass 1's computing half for a scene's streamed run (any rank):
// block b's lines, their window of the scene file read, through the line
// engine along a grid axis (SlarLineEngine) or off the axes
// (slar_stream_oblique.h), with the coherent SAR's halo of lines
// (sar_coherent_stream.h) and the point targets on the block's lines
// (slar_stream_targets.h); the block's own cells' scene-grid maps (or, for
// lines not one per cell, each sample's map values for pass 1m) and the
// median elevation's second pass over its own cells.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ris/scene/scene_stream.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/rank_select.h"
#include "sim/stream/sar_coherent_stream.h"
#include "sim/stream/slant_stream_passes.h"
#include "sim/stream/slar_stream_oblique.h"
#include "sim/stream/slar_stream_targets.h"

namespace ris::detail {

// How a scene's lines run (StreamRun::plan).
struct SceneLineLayout {
  bool oblique = false;     // a track off the grid axes
  bool spill_maps = false;  // scene maps through pass 1m (lines not one per cell)
  bool along_y = false;     // lines are cell rows
  int cross_cells = 0;      // cells across a line (rows or columns)
  int block_lines = 0;
  int fail_block = -1;  // FaultPlan::line_block
};

// What a scene's streamed SLAR or SAR run runs (along a grid axis the
// direct line engine, off the axes slar_stream_oblique.h; the coherent SAR's
// blocks with their halo, sar_coherent_stream.h) and its block length: the
// track and line layout into sim (its radar and derived values set); the
// block lines as requested, else what memory_budget_bytes holds
// (stream_block_lines). fail_block is left for the caller.
SceneLineLayout plan_scene_lines(const Scene& grid, SlarSimulation& sim, int requested_block_lines,
                                 std::int64_t memory_budget_bytes, int ranks);

class SceneLineBlocks {
 public:
  // spare: consumed blocks whose buffers a new block reuses (the pass's).
  SceneLineBlocks(const SceneStreamReader& in, const SlarSimulation& sim, const RadiometrySetup& rs,
                  const std::string& radar_file, const SceneLineLayout& layout,
                  StreamTargets* targets, CoherentStream* coherent, FloatRankSelect& elevation,
                  std::vector<StreamLineBlock>& spare);

  int blocks() const;
  StreamLineBlock compute(int b);

 private:
  StreamLineBlock along_axis(int b);
  StreamLineBlock off_axes(int b);
  void keep_block_maps(const SceneWindow& win, const SceneMapsWindow& maps, StreamLineBlock& k);
  int lines() const { return sim_.geometry.lines; }
  int bins() const { return sim_.image.bins; }

  const SceneStreamReader& in_;
  const SlarSimulation& sim_;
  const SceneLineLayout layout_;
  StreamTargets* targets_;
  CoherentStream* coherent_;
  FloatRankSelect& elevation_;
  std::vector<StreamLineBlock>& spare_;
  std::optional<SlarLineEngine> engine_;
  std::optional<ObliqueBlockLines> oblique_;
  // The block's window of the scene and its maps (along an axis).
  std::vector<float> z_;
  std::vector<std::uint16_t> cat_;
  std::vector<std::uint8_t> ok_;
  std::vector<float> window_incidence_;
  std::vector<std::uint8_t> window_mask_;
};

}  // namespace ris::detail
