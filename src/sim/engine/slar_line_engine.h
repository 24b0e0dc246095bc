// Internal: the line engine every simulation run goes through (SLAR and SAR
// in memory along a grid axis or off it, streamed in blocks, on an
// acquisition's grid; PPI rays):
//
//   line source  ->  per-line stages  ->  profile rows + scene-map sink
//   (terrain of     (look geometry,       (SlarLineProfiles; the source's
//    a line)         radiometry, image     own map writer) + kept-geometry
//                    formation, point      sink (LineKeep: the per-sample
//                    targets)              geometry and element power of
//                                          the whole run, when asked for)
//
// A run supplies a thread source: made once per thread (its scratch and
// buffers), it hands out, once per block of lines, the source that fits the
// block as a std::variant alternative (direct grid rows, a transposed
// column tile, cell by cell, oblique resampling, ...). The engine visits
// the variant once per block and runs the block's lines through that
// source's code: the choice is made per block, never per line or sample.
// A source has
//   LineSpan load(int line, LineScratch& s)   the line's terrain into s
//   void store_maps(int line, const LineSpan&, const LineScratch& s)
//   void finish_block()                        e.g. a tile's maps written back
// A source whose terrain is not a flat-Earth line (an acquisition's radar
// grid on the ellipsoid: sim/sources/acquisition_lines.h; a PPI ray from its site:
// sim/sources/polar_lines.h, in memory or from a streamed block's sampled
// terrain) computes the look geometry itself in
// load() and says so with `static constexpr bool kMakesGeometry = true`;
// the engine then skips line_geometry. Later sources
// (an MPI rank's block range) add a thread source, not a driver.
//
// Blocks go to threads dynamically; each line's profile row and each cell's
// maps are written by one block, so the bytes do not depend on the thread
// count or the schedule. An effect that reads the scene across lines (and
// point targets, the first of them) is a scene-query stage
// (sim/engine/scene_query.h): its contributions to other lines are carried
// and added in a fixed order once the call's lines are formed, so they keep
// that rule.
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <type_traits>
#include <variant>
#include <vector>

#include "ris/util/error.h"
#include "sim/engine/scene_query.h"

#include "sim/engine/slar_line_stages.h"

namespace ris::detail {

// The samples a source put in the scratch: the line's samples [first,
// first + n) as the scratch's elements 0..n, laid out by `layout` (the
// run's geometry, or a span of it).
struct LineSpan {
  int first = 0;
  int n = 0;
  const SlarGeometry* layout = nullptr;
};

// Whether a source computes its lines' look geometry itself (kMakesGeometry).
template <class Source>
constexpr bool makes_geometry() {
  if constexpr (requires { Source::kMakesGeometry; }) {
    return Source::kMakesGeometry;
  } else {
    return false;
  }
}

// Whether a channel's gain table reads each sample's incidence.
inline bool channels_need_incidence(std::span<const ExtraChannel> channels) {
  return std::any_of(channels.begin(), channels.end(),
                     [](const ExtraChannel& c) { return !c.ctx->gain2->uniform(); });
}

// The per-line stages' fixed parts for a run.
struct LineStages {
  const SlarElementContext& ctx;
  LineLookFrame look;
  bool need_incidence = false;  // true when keep->geometry (the kept geometry holds it)
  double range_window_bins = 0.0;
  // The kept-geometry sink and point targets (null: none): each line's
  // geometry, element power and point returns, as the stage path
  // (compute_slar_geometry + form_slar_image) keeps and adds them.
  const LineKeep* keep = nullptr;
  // The run's channels after the first (none: a single-channel run).
  std::span<const ExtraChannel> channels = {};
};

// The run's scene-query stages: the point targets of stages.keep (if any)
// first, then stages.keep->queries.
struct LineQueries {
  std::optional<PointTargetQuery> targets;
  std::vector<const SceneQueryStage*> stages;
  LineQueries(const LineQueries&) = delete;
  LineQueries& operator=(const LineQueries&) = delete;
  explicit LineQueries(const LineKeep* keep) {
    if (!keep) return;
    if (keep->targets) stages.push_back(&targets.emplace(*keep->targets));
    for (const SceneQueryStage* q : keep->queries) stages.push_back(q);
  }
};

// After the lines of an engine call: the contributions the query stages
// carried to other lines. With keep->carried (a streamed block) they all go
// there, for the pass that gathers every block's before adding a line's
// (add_carried_contributions); else (in memory: one call forms every line)
// they are added to prof here, and none may aim outside [line0, line1).
// Either way a line's carried contributions are added once, all together,
// so where blocks start never shows (sim/engine/scene_query.h).
inline void finish_carried(std::vector<LineContribution> carried, const LineStages& stages,
                           int line0, int line1, SlarLineProfiles& prof) {
  if (carried.empty()) return;
  if (stages.keep && stages.keep->carried) {
    std::vector<LineContribution>& out = *stages.keep->carried;
    out.insert(out.end(), carried.begin(), carried.end());
    std::sort(out.begin(), out.end(), contribution_before);
    return;
  }
  const std::vector<LineContribution> rest =
      add_carried_contributions(std::move(carried), line0, line1, stages.range_window_bins, prof);
  RIS_CHECK(rest.empty());
}

// Runs lines [line0, line1) in blocks of block_lines: fills their rows of
// `prof` (allocated), adds to counts and prof.samples_in_swath.
// make_thread_source(LineScratch&) is called once per thread; its result's
// block(b0, b1) returns a std::variant of sources for lines [b0, b1).
template <class MakeThreadSource>
void run_line_blocks(const SlarGeometry& g, const LineStages& stages, int line0, int line1,
                     int block_lines, SlarLineProfiles& prof, SlarLineCounts& counts,
                     MakeThreadSource make_thread_source) {
  const int blocks = (line1 - line0 + block_lines - 1) / block_lines;
  const LineQueries queries(stages.keep);
  std::vector<LineContribution> carried;
  std::int64_t in_swath = 0;
#pragma omp parallel reduction(+ : in_swath)
  {
    LineScratch s(g, prof.bins);
    SlarLineCounts local;
    std::vector<const SlarElementContext*> contexts;
    for (const ExtraChannel& c : stages.channels) contexts.push_back(c.ctx);
    s.elements.reserve_channels(static_cast<int>(contexts.size()));
    auto thread_source = make_thread_source(s);
#pragma omp for schedule(dynamic, 1)
    for (int block = 0; block < blocks; ++block) {
      const int b0 = line0 + block * block_lines, b1 = std::min(line1, b0 + block_lines);
      auto block_source = thread_source.block(b0, b1);
      std::visit(
          [&](auto& source) {
            for (int line = b0; line < b1; ++line) {
              const LineSpan span = source.load(line, s);
              if constexpr (!makes_geometry<std::remove_cvref_t<decltype(source)>>()) {
                line_geometry(*span.layout, stages.look, stages.need_incidence, s);
              }
              in_swath += accumulate_line(stages.ctx, span.n, s, prof, line, local,
                                          stages.range_window_bins, span.first, stages.keep, &g,
                                          queries.stages);
              // The other channels from the same geometry and elements:
              // their power only (the counts are the geometry's).
              if (!stages.channels.empty()) {
                accumulate_channel_lines(stages.channels, contexts, span.n, s, prof, line,
                                         span.first, stages.keep, &g);
              }
              source.store_maps(line, span, s);
            }
            source.finish_block();
          },
          block_source);
    }
#pragma omp critical(ris_slar_line_counts)
    {
      counts.add(local);
      carried.insert(carried.end(), s.carried.begin(), s.carried.end());
    }
  }
  finish_carried(std::move(carried), stages, line0, line1, prof);
  prof.samples_in_swath += in_swath;
  for (const ExtraChannel& c : stages.channels) c.prof->samples_in_swath += in_swath;
}

}  // namespace ris::detail
