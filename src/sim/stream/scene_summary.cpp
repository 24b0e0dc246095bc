#include "sim/stream/scene_summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "ris/util/error.h"

namespace ris::detail {

namespace {

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

}  // namespace

SceneSummary summarise_scene(const SceneStreamReader& in, int row_begin, int row_end,
                             int block_rows, ProgressBar& bar,
                             const std::function<void(std::uint16_t, int, int)>& on_new_category,
                             SceneSummaryElevation elevation) {
  const bool count_elevation = elevation == SceneSummaryElevation::count;
  const Scene& g = in.grid();
  SceneSummary s;
  std::vector<std::uint8_t> seen(65536, 0);
  const std::size_t cap = sz(block_rows) * sz(g.cols);
  std::vector<float> z(cap);
  std::vector<std::uint16_t> cat(cap);
  std::vector<std::uint8_t> ok(cap);
  for (int r0 = row_begin; r0 < row_end; r0 += block_rows) {
    const int n = std::min(block_rows, row_end - r0);
    in.read(r0, n, 0, g.cols, z.data(), cat.data(), ok.data());
    const std::size_t cells = sz(n) * sz(g.cols);
    for (std::size_t i = 0; i < cells; ++i) {
      if (!ok[i]) {
        ++s.nodata_cells;
        continue;
      }
      ++s.valid_cells;
      if (seen[cat[i]] == 0) {
        on_new_category(cat[i], r0 + static_cast<int>(i / sz(g.cols)),
                        static_cast<int>(i % sz(g.cols)));
      }
      seen[cat[i]] = 1;
      const float h = z[i];
      if (h < s.h_min) s.h_min = h;
      if (h > s.h_max) {
        s.h_max = h;
        s.max_row = r0 + static_cast<int>(i / sz(g.cols));
        s.max_col = static_cast<int>(i % sz(g.cols));
      }
      if (count_elevation && std::isfinite(h)) s.elevation.count(h);
    }
    bar.advance(static_cast<std::int64_t>(cells));
  }
  for (std::size_t c = 0; c < seen.size(); ++c)
    if (seen[c]) s.categories.push_back(static_cast<std::uint16_t>(c));
  return s;
}

void reduce_scene_summary(ProcessGroup& g, SceneSummary& s) {
  if (g.size() == 1) return;
  std::vector<std::uint64_t> counts(65536 + 2, 0);
  counts[0] = static_cast<std::uint64_t>(s.valid_cells);
  counts[1] = static_cast<std::uint64_t>(s.nodata_cells);
  for (std::uint16_t c : s.categories) counts[2 + sz(c)] = 1;
  g.sum(counts);
  s.valid_cells = static_cast<std::int64_t>(counts[0]);
  s.nodata_cells = static_cast<std::int64_t>(counts[1]);
  s.categories.clear();
  for (std::size_t c = 0; c < 65536; ++c)
    if (counts[2 + c] > 0) s.categories.push_back(static_cast<std::uint16_t>(c));
  std::vector<std::uint64_t> top = s.elevation.counters();
  g.sum(top);
  s.elevation.set_counters(top);
  struct Extremes {
    float h_min, h_max;
    int max_row, max_col;
  };
  const Extremes mine{s.h_min, s.h_max, s.max_row, s.max_col};
  std::vector<char> bytes(sizeof(Extremes));
  std::memcpy(bytes.data(), &mine, sizeof(Extremes));
  const std::vector<std::vector<char>> all = g.all_gather(bytes);
  s.h_min = std::numeric_limits<float>::infinity();
  s.h_max = -std::numeric_limits<float>::infinity();
  s.max_row = s.max_col = -1;
  for (const std::vector<char>& b : all) {
    Extremes e{};
    RIS_CHECK(b.size() == sizeof(Extremes));
    std::memcpy(&e, b.data(), sizeof(Extremes));
    if (e.h_min < s.h_min) s.h_min = e.h_min;
    if (e.h_max > s.h_max) {
      s.h_max = e.h_max;
      s.max_row = e.max_row;
      s.max_col = e.max_col;
    }
  }
}

SceneSummary summarise_scene_on_ranks(const SceneStreamReader& in, ProcessGroup& g, int block_rows,
                                      ProgressBar& bar, const Sigma0Source& sigma0,
                                      const std::string& backscatter_file,
                                      SceneSummaryElevation elevation) {
  const int rows = in.grid().rows;
  const int row_blocks = (rows + block_rows - 1) / block_rows;
  const auto part_row = [&](int rank) {
    const auto b = std::int64_t(row_blocks) * rank / g.size();
    return static_cast<int>(std::min<std::int64_t>(b * block_rows, rows));
  };
  SceneSummary s = summarise_scene(
      in, part_row(g.rank()), part_row(g.rank() + 1), block_rows, bar,
      [&](std::uint16_t c, int row, int col) {
        if (c == kNoDataCategory || sigma0.has_category(c)) return;
        throw InputError(backscatter_file, "",
                         fmt::format("no backscatter for category {} (the scene {} uses "
                                     "it, first at row {}, column {}; add it to the "
                                     "backscatter file or give another with --backscatter)",
                                     c, in.path(), row, col));
      },
      elevation);
  reduce_scene_summary(g, s);
  return s;
}

}  // namespace ris::detail
