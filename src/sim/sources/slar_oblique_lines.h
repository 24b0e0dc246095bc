// Internal: the parts of the oblique run (a track off the grid axes,
// slar_oblique_lines.cpp) that the streamed oblique run
// (slar_stream_oblique.cpp) shares with it, so that both sample, scan and
// map the same samples and cells: the per-line stages, a line's span loaded
// into the scratch, and the swath's cells of a scene row (cell_sample's
// rule, ris/geometry/scene_geometry_maps.h).
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ris/geometry/scene_geometry_maps.h"
#include "ris/geometry/slar_geometry.h"
#include "sim/engine/slar_line_engine.h"

namespace ris::detail {

// The t with lo <= a0 + t da <= hi, as a closed interval (empty: first >
// second); da == 0: everything or nothing.
std::pair<double, double> affine_range(double a0, double da, double lo, double hi);

// [floor(a) - 1, ceil(b) + 1] clamped to [0, n): a candidate range whose
// cell of margin covers the rounding of the analytic bounds (~1e-12 cells);
// each candidate is then checked exactly. Empty (first == second) when b is
// well below a.
std::pair<int, int> candidates(std::pair<double, double> ab, int n);

// Shrinks [c_begin, c_end) to the cells where `takes` holds, given that they
// are one interval within it.
template <typename Takes>
void trim(int& c_begin, int& c_end, Takes takes) {
  while (c_begin < c_end && !takes(c_begin)) ++c_begin;
  while (c_end > c_begin && !takes(c_end - 1)) --c_end;
}

// The cells of scene row r that take a line and a sample (cell_sample): one
// interval of columns, as both indices are monotone in the column; every
// other cell of the row is outside the swath. Only the scene's grid is read.
std::pair<int, int> swath_cells(const Scene& scene, const CellSampleFrame& f, int r);

// Cells [c0, c1) of a scene row outside the swath: no data where the cell
// has none, outside the swath, NaN incidence.
inline void mark_outside_swath(const std::uint8_t* valid, std::uint8_t* mask, float* incidence,
                               std::size_t c0, std::size_t c1) {
  for (std::size_t i = c0; i < c1; ++i) {
    mask[i] = (valid[i] ? 0 : scene_flag::kNoData) | scene_flag::kOutsideSwath;
    incidence[i] = std::numeric_limits<float>::quiet_NaN();
  }
}

// A scene-map value of a sample that is not seen (outside its line's span).
SampleMapValue unseen_map_value(double near_m, double far_m);

// The per-line stages of an oblique run (as run_oblique_lines sets them up):
// two-way gain table, element context (`bins` range bins) and look frame.
class ObliqueStages {
 public:
  ObliqueStages(const SlarGeometry& g, const Sigma0Lut& lut, const SlarImagingParams& p,
                const std::string& radar_file, int bins, const LineKeep* keep,
                std::span<const ExtraChannel> channels = {});
  ObliqueStages(const ObliqueStages&) = delete;
  ObliqueStages& operator=(const ObliqueStages&) = delete;
  const LineStages& stages() const { return stages_; }

 private:
  TwoWayGainTable gain2_;
  SlarElementContext ctx_;
  LineStages stages_;
};

// A line's span as the scratch's samples 0..n: its terrain by
// sample(span, s) (samples [span.begin, span.end) into s's terrain arrays
// from 0), its u from u_all (every sample's u), and `layout` (the run's
// geometry, copied once) set to the span for the stages.
template <class Sample>
LineSpan load_oblique_span(const SlarGeometry& g, const SlarLineSpan& span,
                           const std::vector<float>& u_all, SlarGeometry& layout, LineScratch& s,
                           Sample sample) {
  const int n = span.end - span.begin;
  const auto first = static_cast<std::ptrdiff_t>(span.begin);
  sample(span, s);
  std::copy(u_all.begin() + first, u_all.begin() + first + n, s.u.begin());
  layout.samples = n;
  layout.first_sample_u_m = g.sample_u_m(span.begin);
  return {span.begin, n, &layout};
}

}  // namespace ris::detail
