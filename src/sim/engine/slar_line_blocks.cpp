#include "ris/sim/slar_line_blocks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>
#include <vector>

#include "kernels/sim/line_block_kernels.h"
#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/image/swath_miss.h"
#include "ris/util/error.h"
#include "ris/util/thread_ranges.h"
#include "ris/util/units.h"
#include "sim/engine/slar_line_engine.h"

namespace ris {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool nearly(double a, double b) {
  return std::abs(a - b) < 1e-9;
}

// The zero bytes in v[i0, i1): 32-bit counts per block, which vectorise
// (std::count's 64-bit count widened every byte: 1.1 ms for the 2000 x 2000
// scene's no-data cells on one thread, this 0.24 ms).
std::int64_t count_zero_bytes(const std::uint8_t* v, std::size_t i0, std::size_t i1) {
  constexpr std::size_t kBlock = 1 << 16;
  std::int64_t total = 0;
  for (std::size_t b = i0; b < i1; b += kBlock) {
    const std::size_t e = std::min(i1, b + kBlock);
    std::uint32_t count = 0;
    for (std::size_t i = b; i < e; ++i) count += v[i] == 0 ? 1u : 0u;
    total += count;
  }
  return total;
}

// Row r of the window (all its columns) and its neighbour rows, or the
// scratch's row of no-data cells beyond the scene's edge.
kernels::CellRow cell_row(const SceneWindow& in, int scene_rows, int r,
                          const detail::LineScratch& s) {
  const std::size_t base = in.index(r, in.col0);
  const float* z = in.elevation_m + base;
  const std::uint8_t* v = in.valid + base;
  const bool north_in = r - 1 >= 0, south_in = r + 1 < scene_rows;
  return {in.cols,
          z,
          v,
          in.category + base,
          north_in ? z - in.cols : s.none_z.data(),
          north_in ? v - in.cols : s.none_valid.data(),
          south_in ? z + in.cols : s.none_z.data(),
          south_in ? v + in.cols : s.none_valid.data()};
}

// The scratch's terrain arrays, the kernels' output.
kernels::LineTerrainOut terrain_out(detail::LineScratch& s) {
  return {s.height.data(),   s.dz_dx.data(), s.dz_dy.data(),
          s.category.data(), s.flags.data(), s.unseen.data()};
}

// Lines along columns (a track heading east or west): a block of lines'
// columns, with one column of margin each side, transposed so that each
// column is one contiguous row; gather_row and map_row then run on it as on
// a row of cells, instead of a per-cell loop with strided reads and writes
// (3.5x the row path's time for the fused stage at 2000 x 2000). Tile row t
// holds scene column cols - 1 - t and tile column k scene row rows - 1 - k:
// with both reversed, gather_row's in-row neighbours (k - 1, k + 1) are the
// cell's south and north neighbours (dz/dy's lo and hi in
// surface_gradient's rule) and its rows above and below (t - 1, t + 1) the
// east and west neighbours (dz/dx's hi and lo): the same slope_difference
// calls as the per-cell rule, with the two slopes coming out swapped and
// the steps exchanged.
struct ColumnTile {
  int scene_cols = 0;
  int c_lo = 0, c_hi = -1;  // scene columns held, inclusive
  int len = 0;              // scene rows: the tile's row length
  std::vector<float> z;
  std::vector<std::uint16_t> cat;
  std::vector<std::uint8_t> valid;
  std::vector<std::uint8_t> mask;  // map_row's output, in the tile's layout
  std::vector<float> deg;

  int row_of_column(int c) const { return scene_cols - 1 - c; }
  int t0() const { return row_of_column(c_hi); }
  std::size_t offset(int c) const {
    return static_cast<std::size_t>(row_of_column(c) - t0()) * static_cast<std::size_t>(len);
  }
  SceneWindow window() const {
    return {t0(), 0, c_hi - c_lo + 1, len, z.data(), cat.data(), valid.data()};
  }
  // Columns [lo, hi] of `in` (which holds every scene row), transposed.
  void load_columns(const SceneWindow& in, int scene_columns, int lo, int hi) {
    scene_cols = scene_columns;
    c_lo = lo;
    c_hi = hi;
    len = in.rows;
    const std::size_t n = static_cast<std::size_t>(hi - lo + 1) * static_cast<std::size_t>(len);
    if (z.size() < n) {
      z.resize(n);
      cat.resize(n);
      valid.resize(n);
      mask.resize(n);
      deg.resize(n);
    }
    // Eight rows by eight columns at a time (transpose_into_tile), the
    // edges one cell at a time.
    const auto one = [&](int r, int c) {
      const std::size_t from = in.index(in.row0 + r, c);
      const std::size_t to = offset(c) + static_cast<std::size_t>(len - 1 - r);
      z[to] = in.elevation_m[from];
      cat[to] = in.category[from];
      valid[to] = in.valid[from];
    };
    const int width = hi - lo + 1;
    const int c8 = lo + width / kernels::kTileLanes * kernels::kTileLanes;
    const int r8 = len / kernels::kTileLanes * kernels::kTileLanes;
    const std::size_t from = in.index(in.row0, lo);
    kernels::transpose_into_tile(r8, c8 - lo, width, static_cast<std::size_t>(len),
                                 static_cast<std::size_t>(in.cols), in.elevation_m + from,
                                 in.category + from, in.valid + from, z.data(), cat.data(),
                                 valid.data());
    for (int r = 0; r < r8; ++r)
      for (int c = c8; c <= hi; ++c) one(r, c);
    for (int r = r8; r < len; ++r)
      for (int c = lo; c <= hi; ++c) one(r, c);
  }
  // The map values of the tile's columns [first, first + n) (each a line
  // of the block) back into the scene grid: eight by eight through
  // registers, as load_columns().
  void store_maps(int first, int n, const SceneMapsWindow& maps) const {
    const auto one = [&](int r, int c) {
      const std::size_t from = offset(c) + static_cast<std::size_t>(len - 1 - r);
      const std::size_t to = maps.index(maps.row0 + r, c);
      maps.mask[to] = mask[from];
      maps.local_incidence_deg[to] = deg[from];
    };
    const int end = first + n;
    const int c8 = first + n / kernels::kTileLanes * kernels::kTileLanes;
    const int r8 = len / kernels::kTileLanes * kernels::kTileLanes;
    // The tile's column `first` is tile row offset(first) / len; the
    // columns after it are the rows before.
    const int tile_rows = static_cast<int>(offset(first) / static_cast<std::size_t>(len)) + 1;
    const std::size_t to = maps.index(maps.row0, first);
    kernels::transpose_from_tile(r8, c8 - first, tile_rows, static_cast<std::size_t>(len),
                                 static_cast<std::size_t>(maps.cols), mask.data(), deg.data(),
                                 maps.mask + to, maps.local_incidence_deg + to);
    for (int r = 0; r < r8; ++r)
      for (int c = c8; c < end; ++c) one(r, c);
    for (int r = r8; r < len; ++r)
      for (int c = first; c < end; ++c) one(r, c);
  }
};

// Lines per block of the column path: the tile (34 columns of 7 bytes a
// cell and the maps' 5: 0.8 MB for 2000 rows) stays in L2, and the two
// margin columns are a small share of its scalar edges. Measured on the
// 2000 x 2000 bench scene at heading 90, fused stage on 1 thread: 8 lines
// 64-68 ms, 16 54 ms, 24 53 ms, 32 52-53 ms (heading 0: 41 ms).
constexpr int kColumnBlockLines = 32;

}  // namespace

SlarLineCounts::SlarLineCounts()
    : r_min_m(std::numeric_limits<float>::infinity()),
      r_max_m(-std::numeric_limits<float>::infinity()) {}

void SlarLineCounts::add(const SlarLineCounts& o) {
  nodata += o.nodata;
  shadow += o.shadow;
  back_facing += o.back_facing;
  layover += o.layover;
  r_min_m = std::min(r_min_m, o.r_min_m);
  r_max_m = std::max(r_max_m, o.r_max_m);
}

bool fused_slar_applies(const Scene& scene, const SlarGeometry& g) {
  if (!g.direct_sampling) return false;
  const bool along_y = nearly(std::abs(g.track.along_y), 1.0);
  const double cell_m = along_y ? scene.dy_m : scene.dx_m;
  const int n = along_y ? scene.rows : scene.cols;
  return g.line_spacing_m == cell_m && g.lines == n;
}

SlarLineEngine::SlarLineEngine(const Scene& scene, const SlarGeometry& layout, const Sigma0Lut& lut,
                               const SlarImagingParams& params, const std::string& radar_file)
    : scene_(scene),
      g_(layout),
      lut_(lut),
      params_(params),
      gain2_(params.elevation_gain, params.peak_gain, radar_file) {
  RIS_CHECK(g_.direct_sampling);
  const Track& t = g_.track;
  const bool along_y = nearly(std::abs(t.along_y), 1.0);
  cross_is_x_ = along_y;
  u_grows_with_index_ = along_y ? t.cross_x > 0.0 : t.cross_y < 0.0;
}

namespace {

// The row (cross_is_x) or column of cells line `line` runs over; -1: none.
int line_cell(const Scene& scene, const SlarGeometry& g, bool cross_is_x, int line) {
  const auto [x, y] = g.track.world_from_along_cross(g.line_s_m(line), 0.0);
  const auto [cf, rf] = scene.grid_from_world(x, y);
  const double f = cross_is_x ? rf : cf;
  const int n = cross_is_x ? scene.rows : scene.cols;
  return (f >= 0.0 && f < n) ? static_cast<int>(std::floor(f)) : -1;
}

// Whether lines [b0, b1) (along columns) each take their own column, the
// columns forming one run [lo, hi]; `scratch` holds them.
bool column_run(const Scene& scene, const SlarGeometry& g, int b0, int b1,
                std::vector<int>& scratch, int& lo, int& hi) {
  scratch.clear();
  for (int line = b0; line < b1; ++line) scratch.push_back(line_cell(scene, g, false, line));
  std::sort(scratch.begin(), scratch.end());
  if (scratch.empty() || scratch.front() < 0) return false;
  lo = scratch.front();
  hi = scratch.back();
  return hi - lo + 1 == b1 - b0 &&
         std::adjacent_find(scratch.begin(), scratch.end()) == scratch.end();
}

}  // namespace

int SlarLineEngine::cell_of_line(int line) const {
  return line_cell(scene_, g_, cross_is_x_, line);
}

void SlarLineEngine::window_for_lines(int line0, int line1, int& row0, int& rows, int& col0,
                                      int& cols) const {
  int lo = std::numeric_limits<int>::max(), hi = -1;
  for (int line : {line0, line1 - 1}) {
    const int c = line_cell(scene_, g_, cross_is_x_, line);
    if (c < 0) continue;
    lo = std::min(lo, c);
    hi = std::max(hi, c);
  }
  const int n = cross_is_x_ ? scene_.rows : scene_.cols;
  if (hi < 0) {
    lo = 0;
    hi = -1;
  } else {
    lo = std::max(0, lo - 1);
    hi = std::min(n - 1, hi + 1);
  }
  if (cross_is_x_) {
    row0 = lo;
    rows = hi - lo + 1;
    col0 = 0;
    cols = scene_.cols;
  } else {
    col0 = lo;
    cols = hi - lo + 1;
    row0 = 0;
    rows = scene_.rows;
  }
}

namespace {

using detail::LineSpan;

// ---- The direct line sources: one line per cell row or column ----------
// (as slar_geometry.cpp fill_line with its DirectSampler, the slope computed
// in place as surface_gradient). Chosen per block by DirectThreadSource.

// What every direct source of a run reads.
struct DirectRun {
  const Scene& scene;
  const SlarGeometry& g;
  const SceneWindow& in;
  const SceneMapsWindow& maps;
  bool cross_is_x;
  bool u_grows_with_index;
  double near_m, far_m;
  const SampleMapRows* sample_maps;

  int cell(int line) const { return line_cell(scene, g, cross_is_x, line); }
  // Whether the sources write the scene maps (a run whose lines are not
  // one per row or column makes them from the kept geometry instead).
  bool writes_maps() const { return maps.mask != nullptr; }
  // Every sample's map value of the line (SampleMapRows), from the scratch
  // as keep_line_geometry keeps it for scene_geometry_maps.
  void store_sample_maps(int line, const detail::LineScratch& s) const {
    if (sample_maps == nullptr) return;
    const std::size_t row =
        static_cast<std::size_t>(line - sample_maps->line0) * static_cast<std::size_t>(g.samples);
    for (int j = 0; j < g.samples; ++j) {
      const std::size_t jj = static_cast<std::size_t>(j);
      const SampleMapValue v =
          scene_map_sample(s.flags[jj], s.range[jj], s.local_incidence[jj], near_m, far_m);
      sample_maps->mask[row + jj] = v.mask;
      sample_maps->local_incidence_deg[row + jj] = v.local_incidence_deg;
    }
  }
  LineSpan whole() const { return {0, g.samples, &g}; }
  // Sample j of the line over row or column lc: its cell.
  void cell_of(int lc, int j, int& r, int& c) const {
    if (cross_is_x) {
      r = lc;
      c = u_grows_with_index ? j : scene.cols - 1 - j;
    } else {
      c = lc;
      r = u_grows_with_index ? j : scene.rows - 1 - j;
    }
  }
  // A line beyond the scene: every sample unseen, no terrain.
  void load_outside(detail::LineScratch& s) const {
    for (int j = 0; j < g.samples; ++j) {
      const std::size_t jj = static_cast<std::size_t>(j);
      s.flags[jj] = sample_flag::kUnseen;
      s.height[jj] = s.dz_dx[jj] = s.dz_dy[jj] = kNaN;
      s.category[jj] = 0;
    }
  }
};

// Any window, cell by cell (the reference rule).
struct CellSource {
  const DirectRun& run;
  int lc = -1;

  LineSpan load(int line, detail::LineScratch& s) {
    lc = run.cell(line);
    if (lc < 0) {
      run.load_outside(s);
      return run.whole();
    }
    const Scene& scene = run.scene;
    const SceneWindow& in = run.in;
    const auto ok = [&](int r, int c) {
      return scene.contains(r, c) && in.valid[in.index(r, c)] != 0;
    };
    const auto z = [&](int r, int c) {
      return scene.contains(r, c) ? in.elevation_m[in.index(r, c)] : 0.0f;
    };
    for (int j = 0; j < run.g.samples; ++j) {
      const std::size_t jj = static_cast<std::size_t>(j);
      int r = 0, c = 0;
      run.cell_of(lc, j, r, c);
      const bool valid = in.valid[in.index(r, c)] != 0;
      std::uint8_t f = valid ? 0 : sample_flag::kNoData;
      if (!(run.g.sample_u_m(j) > 0.0)) f |= sample_flag::kUnseen;
      s.flags[jj] = f;
      if (!valid) {
        s.height[jj] = s.dz_dx[jj] = s.dz_dy[jj] = kNaN;
        s.category[jj] = 0;
        continue;
      }
      const std::size_t i = in.index(r, c);
      const float zc = in.elevation_m[i];
      s.height[jj] = zc;
      s.dz_dx[jj] =
          slope_difference(ok(r, c - 1), z(r, c - 1), ok(r, c + 1), z(r, c + 1), zc, scene.dx_m);
      // North (+y) is towards row r - 1.
      s.dz_dy[jj] =
          slope_difference(ok(r + 1, c), z(r + 1, c), ok(r - 1, c), z(r - 1, c), zc, scene.dy_m);
      s.category[jj] = in.category[i];
    }
    return run.whole();
  }
  // The scene-grid maps (scene_geometry_maps: each cell is its own sample).
  void store_maps(int line, const LineSpan&, const detail::LineScratch& s) const {
    run.store_sample_maps(line, s);
    if (lc < 0 || !run.writes_maps()) return;
    for (int j = 0; j < run.g.samples; ++j) {
      const std::size_t jj = static_cast<std::size_t>(j);
      int r = 0, c = 0;
      run.cell_of(lc, j, r, c);
      const std::size_t cell = run.maps.index(r, c);
      scene_map_cell(run.in.valid[run.in.index(r, c)] != 0, s.flags[jj], s.range[jj],
                     s.local_incidence[jj], run.near_m, run.far_m, run.maps.mask[cell],
                     run.maps.local_incidence_deg[cell]);
    }
  }
  void finish_block() const {}
};

// Lines along rows whose window and maps hold whole rows: a row of cells,
// contiguous in memory, by the row kernels.
struct RowSource {
  const DirectRun& run;
  int lc = -1;

  LineSpan load(int line, detail::LineScratch& s) {
    lc = run.cell(line);
    if (lc < 0) {
      run.load_outside(s);
    } else {
      kernels::gather_row(cell_row(run.in, run.scene.rows, lc, s), run.scene.dx_m, run.scene.dy_m,
                          !run.u_grows_with_index, terrain_out(s));
    }
    return run.whole();
  }
  void store_maps(int line, const LineSpan&, const detail::LineScratch& s) const {
    run.store_sample_maps(line, s);
    if (lc < 0 || !run.writes_maps()) return;
    kernels::map_row(run.g.samples, !run.u_grows_with_index, run.near_m, run.far_m, s.flags.data(),
                     s.range.data(), s.local_incidence.data(), run.in.valid + run.in.index(lc, 0),
                     run.maps.mask + run.maps.index(lc, 0),
                     run.maps.local_incidence_deg + run.maps.index(lc, 0));
  }
  void finish_block() const {}
};

// A block of lines along columns, each column a row of the transposed tile
// (ColumnTile): the row kernels with the steps exchanged and the slopes
// swapped back; the tile's maps written back at the block's end.
struct TileSource {
  const DirectRun& run;
  ColumnTile& tile;
  int lo = 0, hi = -1;  // the block's columns
  int lc = -1;

  LineSpan load(int line, detail::LineScratch& s) {
    lc = run.cell(line);
    kernels::gather_row(cell_row(tile.window(), run.scene.cols, tile.row_of_column(lc), s),
                        run.scene.dy_m, run.scene.dx_m, run.u_grows_with_index, terrain_out(s));
    std::swap(s.dz_dx, s.dz_dy);
    return run.whole();
  }
  void store_maps(int line, const LineSpan&, const detail::LineScratch& s) const {
    run.store_sample_maps(line, s);
    const std::size_t at = tile.offset(lc);
    kernels::map_row(run.g.samples, run.u_grows_with_index, run.near_m, run.far_m, s.flags.data(),
                     s.range.data(), s.local_incidence.data(), tile.valid.data() + at,
                     tile.mask.data() + at, tile.deg.data() + at);
  }
  void finish_block() const { tile.store_maps(lo, hi - lo + 1, run.maps); }
};

using DirectSource = std::variant<RowSource, TileSource, CellSource>;

// One thread's direct sources: the row path when the window and the maps
// hold whole rows; along columns, the tile when the block's lines take one
// run of distinct columns and the window holds every scene row; else cell
// by cell.
struct DirectThreadSource {
  const DirectRun& run;
  bool rows;
  bool column_tiles;
  ColumnTile tile;
  std::vector<int> columns;

  DirectSource block(int b0, int b1) {
    if (rows) return RowSource{run};
    int lo = 0, hi = -1;
    if (column_tiles && column_run(run.scene, run.g, b0, b1, columns, lo, hi)) {
      // The tile adds one column of margin each side.
      tile.load_columns(run.in, run.scene.cols, std::max(0, lo - 1),
                        std::min(run.scene.cols - 1, hi + 1));
      return TileSource{run, tile, lo, hi};
    }
    return CellSource{run};
  }
};

}  // namespace

void SlarLineEngine::run(int line0, int line1, const SceneWindow& in, SlarLineProfiles& prof,
                         const SceneMapsWindow& maps, SlarLineCounts& counts,
                         const detail::LineKeep* keep, const SampleMapRows* sample_maps,
                         std::span<const detail::ExtraChannel> channels) const {
  const SlarGeometry& g = g_;
  const Track& t = g.track;
  const int samples = g.samples;
  const detail::SlarElementContext ctx = detail::element_context(params_, gain2_, lut_, prof.bins);
  const detail::LineStages stages{
      ctx,
      LineLookFrame{g.altitude_m, t.cross_x, t.cross_y, g.line_spacing_m * g.sample_step_m},
      !gain2_.uniform() || (keep && keep->geometry) || detail::channels_need_incidence(channels),
      params_.range_window_bins,
      keep,
      channels};
  const DirectRun run{scene_,
                      g,
                      in,
                      maps,
                      cross_is_x_,
                      u_grows_with_index_,
                      params_.range.near_m,
                      params_.range.far_m(),
                      sample_maps};
  const bool no_maps = maps.mask == nullptr;
  const bool rows = cross_is_x_ && in.col0 == 0 && in.cols == samples &&
                    (no_maps || (maps.col0 == 0 && maps.cols == samples));
  // Lines along columns whose window holds every scene row go by blocks
  // through a transposed tile (which writes the maps back).
  const bool column_tiles = !no_maps && !cross_is_x_ && in.row0 == 0 && in.rows == samples &&
                            maps.row0 == 0 && maps.rows == samples;
  const int block_lines = keep && keep->block_lines > 0 ? keep->block_lines
                          : column_tiles                ? kColumnBlockLines
                                                        : 16;
  detail::run_line_blocks(g, stages, line0, line1, block_lines, prof, counts,
                          [&](detail::LineScratch&) {
                            return DirectThreadSource{run, rows, column_tiles, {}, {}};
                          });
}

void check_swath_hits_scene(std::int64_t samples_in_swath, const SlantRangeBins& range,
                            const SlarLineCounts& counts, const std::string& radar_file,
                            const std::string& view_key) {
  if (samples_in_swath > 0) return;
  throw_swath_misses_scene(radar_file, range, counts.r_min_m, counts.r_max_m, view_key);
}

bool fused_slar_image_applies(const Scene& scene, const SlarGeometry& layout) {
  return fused_slar_applies(scene, layout) || !layout.direct_sampling;
}

namespace {

// Every cell row or column taken by exactly one line (the sources then
// write every cell's maps once).
void check_one_line_per_cell(const SlarLineEngine& engine, const SlarGeometry& g,
                             const Scene& scene) {
  RIS_CHECK(static_cast<std::size_t>(g.lines) * static_cast<std::size_t>(g.samples) ==
            scene.size());
  std::vector<std::uint8_t> taken(static_cast<std::size_t>(g.lines), 0);
  for (int line = 0; line < g.lines; ++line) {
    const int cell = engine.cell_of_line(line);
    RIS_CHECK(cell >= 0 && cell < g.lines && !taken[static_cast<std::size_t>(cell)]);
    taken[static_cast<std::size_t>(cell)] = 1;
  }
}

// The scene cells without data, counted by the threads (a serial count over
// the scene was a serial step).
std::int64_t count_nodata_cells(const Scene& scene) {
  std::int64_t nodata_cells = 0;
  for_thread_ranges(scene.size(), [&](std::size_t i0, std::size_t i1) {
    const std::int64_t part = count_zero_bytes(scene.valid.data(), i0, i1);
#pragma omp atomic
    nodata_cells += part;
  });
  return nodata_cells;
}

}  // namespace

SlarImage form_slar_image_fused(const Scene& scene, SlarGeometry& g, SceneGeometryMaps& maps,
                                const Sigma0Lut& lut, const SlarImagingParams& p,
                                const std::string& radar_file, const SlarEngineKeep& keep,
                                std::span<const SlarImageChannel> channels) {
  // Lines not one per cell row or column leave the maps to the kept geometry.
  const bool source_maps = fused_slar_image_applies(scene, g);
  RIS_CHECK(source_maps || keep.geometry);
  RIS_CHECK(p.range.count > 0 && p.range.bin_m > 0.0);
  RIS_CHECK(p.azimuth_beamwidth_rad > 0.0);
  SlarLineProfiles prof;
  prof.allocate(g.lines, p.range.count);
  // The kept-geometry sink (its arrays allocated below, after the engine
  // has copied the layout) and the point targets.
  std::vector<float> element_power;
  if (keep.element_power) {
    element_power.assign(static_cast<std::size_t>(g.lines) * static_cast<std::size_t>(g.samples),
                         0.0f);
  }
  std::vector<PointCandidate> candidates;  // in target order
  std::optional<detail::LinePointTargets> targets;
  if (keep.targets && !keep.targets->empty()) {
    candidates = point_candidates(*keep.targets, scene, g);
    targets.emplace(candidates);
  }
  detail::LineKeep line_keep{keep.geometry ? &g : nullptr,
                             keep.element_power ? element_power.data() : nullptr,
                             targets ? &*targets : nullptr};
  line_keep.block_lines = keep.block_lines;
  const detail::LineKeep* kept = line_keep.geometry || line_keep.element_power_w ||
                                         line_keep.targets || line_keep.block_lines > 0
                                     ? &line_keep
                                     : nullptr;
  // The other channels: each its gain table, element context and profiles.
  const std::size_t nc = channels.size();
  std::vector<TwoWayGainTable> gain2;
  gain2.reserve(nc);
  std::vector<detail::SlarElementContext> ctx(nc);
  std::vector<SlarLineProfiles> profs(nc);
  std::vector<detail::ExtraChannel> extra(nc);
  std::vector<std::vector<float>> channel_power(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    const SlarImagingParams& pc = *channels[c].params;
    if (channels[c].keep_element_power) {
      RIS_CHECK(keep.element_power);
      channel_power[c].assign(element_power.size(), 0.0f);
    }
    RIS_CHECK(pc.range.count == p.range.count && pc.range.near_m == p.range.near_m &&
              pc.range.bin_m == p.range.bin_m);
    gain2.emplace_back(pc.elevation_gain, pc.peak_gain, radar_file);
    profs[c].allocate(g.lines, p.range.count);
    ctx[c] = detail::element_context(pc, gain2[c], *channels[c].lut, p.range.count);
    extra[c] = {&ctx[c], pc.range_window_bins, &profs[c],
                channel_power[c].empty() ? nullptr : channel_power[c].data()};
  }
  SlarLineCounts counts;
  if (g.direct_sampling) {
    const SlarLineEngine engine(scene, g, lut, p, radar_file);
    if (keep.geometry) g.allocate_samples();
    SceneMapsWindow out;
    if (source_maps) {
      check_one_line_per_cell(engine, g, scene);
      // No fill (UninitVector): every cell is written by the line on its row
      // or column.
      maps.mask.resize(scene.size());
      maps.local_incidence_deg.resize(scene.size());
      out = {0, 0, scene.rows, scene.cols, maps.mask.data(), maps.local_incidence_deg.data()};
    }
    engine.run(0, g.lines, SceneWindow::whole(scene), prof, out, counts, kept, nullptr, extra);
  } else {
    if (keep.geometry) g.allocate_samples();
    // The oblique path sets every cell first itself.
    maps.mask.resize(scene.size());
    maps.local_incidence_deg.resize(scene.size());
    detail::run_oblique_lines(scene, g, lut, p, radar_file, prof, maps, counts, kept, extra);
  }
  set_sample_counts(g, counts);
  g.nodata_cells = count_nodata_cells(scene);
  check_swath_hits_scene(prof.samples_in_swath, p.range, counts, radar_file);
  for (std::size_t c = 0; c < nc; ++c) {
    *channels[c].image = slar_image_from_profiles(profs[c], *channels[c].params, g.line_spacing_m);
    if (!channel_power[c].empty()) channels[c].image->element_power_w = std::move(channel_power[c]);
  }
  SlarImage img = slar_image_from_profiles(prof, p, g.line_spacing_m);
  if (keep.element_power) img.element_power_w = std::move(element_power);
  if (targets) {
    // In target order, as point_returns_on_lines gives them, with the
    // power of each seen one.
    std::vector<std::uint8_t> lit(candidates.size(), 0);
    std::vector<double> power(keep.targets->size(), 0.0);
    std::vector<std::uint8_t> lit_target(keep.targets->size(), 0);
    for (std::size_t k = 0; k < targets->by_line.size(); ++k) {
      lit_target[targets->by_line[k].target] = targets->lit[k];
      power[targets->by_line[k].target] = targets->power_w[k];
    }
    for (std::size_t c = 0; c < candidates.size(); ++c) {
      lit[c] = lit_target[candidates[c].target];
      if (lit[c]) img.point_power_w.push_back(power[candidates[c].target]);
    }
    std::vector<PointReturn> seen =
        seen_point_returns(*keep.targets, candidates, lit, keep.hidden_targets);
    if (keep.point_returns) *keep.point_returns = std::move(seen);
  }
  if (!source_maps) maps = scene_geometry_maps(scene, g, p.range);
  return img;
}

void set_sample_counts(SlarGeometry& g, const SlarLineCounts& counts) {
  g.nodata_samples = counts.nodata;
  g.shadow_samples = counts.shadow;
  g.back_facing_samples = counts.back_facing;
  g.layover_samples = counts.layover;
}

SlarImage slar_image_from_profiles(SlarLineProfiles& prof, const SlarImagingParams& p,
                                   double line_spacing_m) {
  SlarImage img;
  img.lines = prof.lines;
  img.bins = p.range.count;
  img.range = p.range;
  img.line_spacing_m = line_spacing_m;
  img.samples_in_swath = prof.samples_in_swath;
  integrate_slar_azimuth(prof, p, line_spacing_m, img);
  img.mapped_count = std::move(prof.mapped_count);
  img.visible_count = std::move(prof.visible_count);
  return img;
}

}  // namespace ris
