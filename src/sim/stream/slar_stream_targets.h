// Internal: point targets (ris/sim/point_target.h) in a streamed SLAR or
// incoherent SAR run (ris/sim/slar_stream.h), along a grid axis or off it
// (the line engine's blocks or slar_stream_oblique.h's), with the in-memory
// run's bytes.
//
// The in-memory run places each target on its line before the lines are
// formed (point_candidates) and finds it lit or hidden as its line is formed
// (the line engine's LinePointTargets); its power goes into that line's
// range profile, and the azimuth integration spreads it over the lines its
// footprint reaches. A streamed run does the same per block of lines:
//
//   - every rank places the targets once, their base height read from the
//     four cells around each (a window of the scene file: the bilinear
//     sample of terrain_height_at, the same cells and weights), after the
//     same checks as check_point_targets_on_scene (same messages);
//   - a block's engine run gets the candidates on its own lines
//     (candidates_on_lines), and its result carries, per candidate, whether
//     it was lit and its power (BlockTargets: packed with the block under
//     MPI);
//   - rank 0 collects the blocks' results (add), keeps each target's
//     measurement window of the image as the lines are emitted in order
//     (observe: the mean power before NaN for no data, or the coherent
//     intensity), and at the end sets the returns seen, the names hidden
//     and their powers as form_slar_image_fused does (finish), measures them
//     (measure: measure_point_target_in_window, the numbers of
//     measure_point_targets) and gives metadata.json's "point_targets".
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/scene/scene_stream.h"
#include "ris/sim/point_target.h"
#include "ris/sim/point_target_irf.h"
#include "ris/sim/slar_simulation.h"
#include "sim/engine/slar_line_stages.h"

namespace ris::detail {

// A block's targets as its engine run found them: per candidate on its
// lines (index into StreamTargets::candidates), lit or not, and its power.
struct BlockTargets {
  std::vector<std::int32_t> candidate;
  std::vector<std::uint8_t> lit;
  std::vector<double> power_w;
};

// Appends the block's targets to a message / reads them back from [p, end)
// (p advanced past them).
void pack_block_targets(const BlockTargets& t, std::vector<char>& out);
BlockTargets unpack_block_targets(const char*& p, const char* end);

// The terrain height at (x, y) as terrain_height_at gives it on the whole
// scene (bilinear over the four cells around, NaN off the scene or touching
// no data), from those cells read out of the scene file.
double streamed_terrain_height(const SceneStreamReader& in, double x_m, double y_m);

// The targets checked on the scene (InputError as
// check_point_targets_on_scene: off the scene, on a no-data cell) and the
// terrain height under each (streamed_terrain_height), in target order.
std::vector<double> streamed_target_heights(const std::vector<PointTarget>& targets,
                                            const SceneStreamReader& in);

class StreamTargets {
 public:
  // Checks the targets on the scene (InputError as
  // check_point_targets_on_scene) and places them on the layout g's lines
  // (as point_candidates). img: the image's layout (lines, bins, range) for
  // the measurement windows.
  StreamTargets(const std::vector<PointTarget>& targets, std::string targets_file,
                const SceneStreamReader& in, const SlarGeometry& g, const SlarImage& img);

  const std::vector<PointCandidate>& candidates() const { return candidates_; }

  // The candidates on lines [l0, l1) for the engine (none: nullopt), and
  // the block's result from them after the run.
  std::optional<LinePointTargets> candidates_on_lines(int l0, int l1) const;
  BlockTargets block_result(const LinePointTargets& t) const;

  // Rank 0, blocks in any order: the candidates' lit flags and powers.
  void add(const BlockTargets& b);
  // Rank 0, lines in order: image lines [k0, k0 + n) (n x bins) of the
  // image measured.
  void observe(int k0, int n, const float* power);

  // Rank 0, after every block: sim's point_returns, hidden_targets and
  // image.point_power_w as an in-memory run sets them.
  void finish(SlarSimulation& sim) const;
  // The measurements (after finish) and metadata.json's "point_targets".
  std::vector<PointTargetIrf> measure(const SlarSimulation& sim, bool coherent) const;
  nlohmann::json metadata(const std::vector<PointTargetIrf>& irfs, const SlarSimulation& sim,
                          bool coherent) const;

 private:
  const std::vector<PointTarget>& targets_;
  std::string file_;
  int bins_ = 0;
  std::vector<PointCandidate> candidates_;  // in target order
  std::vector<std::uint8_t> lit_;
  std::vector<double> power_w_;
  // Per candidate: its measurement window and the pixels kept so far.
  std::vector<std::optional<IrfWindow>> windows_;
  std::vector<std::vector<float>> window_power_;
};

}  // namespace ris::detail
