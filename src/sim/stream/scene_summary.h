// Internal: pass 0 of a scene's streamed run, what simulate_slar learns from
// the whole scene before it starts (cells with data, categories, height
// range and the first highest cell, the median elevation's first pass),
// over each rank's rows, and the whole scene's from every rank's part.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <vector>

#include <string>

#include "ris/backscatter/sigma0_source.h"
#include "ris/scene/scene_stream.h"
#include "ris/util/process_group.h"
#include "ris/util/progress.h"
#include "ris/util/rank_select.h"

namespace ris::detail {

struct SceneSummary {
  std::int64_t valid_cells = 0;
  std::int64_t nodata_cells = 0;
  std::vector<std::uint16_t> categories;  // of the cells with data, sorted
  float h_min = std::numeric_limits<float>::infinity();
  float h_max = -std::numeric_limits<float>::infinity();
  int max_row = -1, max_col = -1;  // the first highest cell with data
  FloatRankSelect elevation;       // pass 1 of the median elevation (when asked)
};

// What pass 0 counts beyond the summary: the median elevation's first pass
// (a SLAR's ground-range reference; a PPI has none).
enum class SceneSummaryElevation { count, skip };

// on_new_category(c, row, col): called at the first cell of each category,
// so a category the backscatter source lacks stops the run there rather
// than after the whole pass.
// Rows [row_begin, row_end) (an MPI rank's part; reduce_scene_summary
// combines the parts).
SceneSummary summarise_scene(const SceneStreamReader& in, int row_begin, int row_end,
                             int block_rows, ProgressBar& bar,
                             const std::function<void(std::uint16_t, int, int)>& on_new_category,
                             SceneSummaryElevation elevation = SceneSummaryElevation::count);

// The whole scene's summary from every rank's part (rows in rank order),
// on every rank: counts summed, categories merged, and the extremes folded
// in rank order with the same strict comparisons as summarise_scene, so the
// highest cell is the first in row order, as one process finds it.
void reduce_scene_summary(ProcessGroup& g, SceneSummary& s);

// Pass 0 of a streamed run: this rank's rows (whole blocks of block_rows,
// split evenly over g's ranks), every category checked against the
// backscatter source at its first cell (InputError naming
// backscatter_file: a scene of one undefined category fails at once, not
// after the pass; in an MPI run, the first in the rank's rows), then the
// whole scene's summary on every rank.
SceneSummary summarise_scene_on_ranks(
    const SceneStreamReader& in, ProcessGroup& g, int block_rows, ProgressBar& bar,
    const Sigma0Source& sigma0, const std::string& backscatter_file,
    SceneSummaryElevation elevation = SceneSummaryElevation::count);

}  // namespace ris::detail
