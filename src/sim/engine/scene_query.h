// Internal: the line engine's scene-query stage (docs/design.md, "Cross-line
// effects: the scene-query stage"). After a line's look geometry and its
// terrain's elements, each of the run's query stages may look at the scene
// (the line's own scratch, or the scene, or later a 3-D object set, at any
// line) and emit contributions: power added to any (line, range bin) of the
// run. The engine adds them in a fixed order, so the bytes do not depend on
// the thread count, the block size or the rank count:
//
//   - a contribution to the line being formed (line == the queried line) is
//     added to the line's double accumulator after its terrain elements and
//     before the range window, in (bin, stage, source, seq) order;
//   - a contribution to another line is carried: every block's carried
//     contributions are gathered and sorted by (line, bin, stage, source,
//     from_line, seq); once all of a line's are in, they are summed in that
//     order into a row of zeros, passed through the same range window and
//     added to the line's profile row, once. In memory the engine call,
//     which forms every line, does it at its end; a streamed run's engine
//     call (one block) hands them to LineKeep::carried and the pass that
//     gathers every block's (under MPI: rank 0, the sink) adds a line's
//     before it integrates it (add_carried_contributions).
//
// Which of the two a contribution takes depends only on its source and
// target lines, never on where blocks start; a query sees only its line
// (and what it reads itself from the scene), so each contribution is the same
// wherever and by whichever thread its line is formed.
//
// Point targets are the first query stage (PointTargetQuery): each target on
// its line, lit or hidden by the line's terrain, its radar-equation power
// into its bin (MODEL.md: the point-target radar equation), as
// form_slar_image adds point_returns_on_lines's returns: the same bytes.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "kernels/image/slar_element.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/image/slar_image.h"

namespace ris::detail {

struct LineScratch;
struct LinePointTargets;

// One contribution of a query stage. The stage sets line, bin, source and
// power_w; the engine sets stage, from_line and seq.
struct LineContribution {
  int line = 0;              // target line (the run's numbering)
  int bin = 0;               // range bin of its profile, [0, bins)
  std::uint64_t source = 0;  // the stage's id of the scatterer (a target's index, ...)
  double power_w = 0.0;      // mean power added, W
  int stage = 0;             // the stage's index among the run's query stages
  int from_line = 0;         // the line whose query emitted it
  int seq = 0;               // its order among that query's contributions
};

// The fixed order contributions are added in: (line, bin, stage, source,
// from_line, seq), a total order (seq breaks every tie).
bool contribution_before(const LineContribution& a, const LineContribution& b);

// What a query sees of the line being formed: its samples [first, first +
// n) in the scratch (flags, heights, ranges, ... after line geometry), the
// run's layout and the channel's element context (radar equation, gain
// table, range bins).
struct LineQuery {
  int line = 0;
  int first = 0;
  int n = 0;
  const SlarGeometry& layout;
  const LineScratch& s;
  const SlarElementContext& ctx;
};

// A scene-query stage. query() is called once per line formed, from any
// thread, for different lines at once: it may read anything shared but
// write only state that belongs to its line (as PointTargetQuery writes its
// line's targets' lit flags). It appends its contributions to `out`.
class SceneQueryStage {
 public:
  virtual ~SceneQueryStage() = default;
  virtual void query(const LineQuery& q, std::vector<LineContribution>& out) const = 0;
};

// Point targets placed by the hook: the targets on the queried line that its
// terrain leaves lit (point_lit_on_samples), their power k_radar G^2(beta)
// sigma / R^4 into the bin of their slant range (dropped outside the swath);
// each one's lit flag and power recorded in `targets` (by_line order).
class PointTargetQuery final : public SceneQueryStage {
 public:
  explicit PointTargetQuery(LinePointTargets& targets) : targets_(targets) {}
  void query(const LineQuery& q, std::vector<LineContribution>& out) const override;

 private:
  LinePointTargets& targets_;
};

// Runs the stages for the line in q: adds its own contributions to acc (the
// line's double accumulator, q.ctx.bins long) in the fixed order and appends
// those for other lines to `carried`. `scratch`: the thread's reusable list.
void query_line(std::span<const SceneQueryStage* const> stages, const LineQuery& q, double* acc,
                std::vector<LineContribution>& scratch, std::vector<LineContribution>& carried);

// Adds carried contributions (sorted here) whose line is in [line0, line1)
// to prof: per line, summed in order into a row of zeros, the range window
// applied (window_bins > 0), each bin added to its power_w. Returns those
// aimed at other lines, sorted.
std::vector<LineContribution> add_carried_contributions(std::vector<LineContribution> carried,
                                                        int line0, int line1, double window_bins,
                                                        SlarLineProfiles& prof);

}  // namespace ris::detail
