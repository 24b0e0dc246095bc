#include "sim/stream/scene_line_blocks.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "ris/geometry/slar_geometry.h"
#include "ris/sensor/track_view.h"
#include "ris/sim/slar_run_setup.h"
#include "ris/util/error.h"

namespace ris::detail {

namespace {

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

}  // namespace

SceneLineLayout plan_scene_lines(const Scene& grid, SlarSimulation& sim, int requested_block_lines,
                                 std::int64_t memory_budget_bytes, int ranks) {
  const RadarParams& r = sim.radar;
  sim.track = resolve_track(r.track, grid, r.source_file);
  check_scene_in_view(r.track, sim.track, grid, r.source_file);
  sim.geometry = slar_geometry_layout(grid, sim.track, r.azimuth_line_spacing_m);
  const SlarGeometry& g = sim.geometry;
  const int lines = g.lines, bins = sim.derived.range_bins;
  SceneLineLayout l;
  // A track off the axes: its lines through slar_stream_oblique.h, ~30
  // bytes a sample (the sampled terrain, map values and their copies).
  l.oblique = !g.direct_sampling;
  // Whether the track runs along y (lines are cell rows), as fused_slar_applies.
  l.along_y = std::abs(std::abs(sim.track.along_y) - 1.0) < 1e-9;
  // The coherent SAR also keeps each element's power and slant range (8
  // bytes a sample), and per bin its range-compressed lines, z and
  // intensity (twice: sent).
  const bool coherent = r.mode == RadarMode::sar && r.sar.coherent;
  // Lines not one per cell row or column (off the axes, or along one at a
  // spacing other than the cell size): each sample's map values are spilled
  // and pass 1m takes each cell's (as scene_geometry_maps).
  l.spill_maps = !fused_slar_applies(grid, g);
  l.cross_cells =
      l.oblique
          ? static_cast<int>(std::max<std::int64_t>(1, std::int64_t(grid.rows) * grid.cols / lines))
          : (l.along_y ? grid.cols : grid.rows);
  // Along an axis a line reads spacing / cell rows or columns (at least
  // one) and, spilled, keeps 5 bytes a sample.
  const double cells_per_line =
      l.oblique ? 1.0 : std::max(1.0, g.line_spacing_m / (l.along_y ? grid.dy_m : grid.dx_m));
  const std::int64_t per_line =
      (l.oblique ? std::int64_t(g.samples) * (coherent ? 38 : 30)
                 : std::int64_t(std::ceil(l.cross_cells * cells_per_line)) * (coherent ? 26 : 18) +
                       (l.spill_maps ? std::int64_t(g.samples) * 5 : 0)) +
      std::int64_t(std::max(bins, 1)) * (coherent ? 112 : 72);
  l.block_lines =
      stream_block_lines(lines, per_line, requested_block_lines, memory_budget_bytes, ranks);
  return l;
}

SceneLineBlocks::SceneLineBlocks(const SceneStreamReader& in, const SlarSimulation& sim,
                                 const RadiometrySetup& rs, const std::string& radar_file,
                                 const SceneLineLayout& layout, StreamTargets* targets,
                                 CoherentStream* coherent, FloatRankSelect& elevation,
                                 std::vector<StreamLineBlock>& spare)
    : in_(in),
      sim_(sim),
      layout_(layout),
      targets_(targets),
      coherent_(coherent),
      elevation_(elevation),
      spare_(spare) {
  if (layout.oblique) {
    oblique_.emplace(in.grid(), sim.geometry, rs.lut, rs.imaging, radar_file, bins());
  } else {
    engine_.emplace(in.grid(), sim.geometry, rs.lut, rs.imaging, radar_file);
  }
  const int halo = coherent_ ? 2 * coherent_->halo_lines() : 0;  // the coherent SAR's
  const std::size_t cap =
      layout.oblique ? 0 : sz(layout.block_lines + halo + 2) * sz(layout.cross_cells);
  z_.resize(cap);
  cat_.resize(cap);
  ok_.resize(cap);
  window_incidence_.resize(cap);
  window_mask_.resize(cap);
}

int SceneLineBlocks::blocks() const {
  return (lines() + layout_.block_lines - 1) / layout_.block_lines;
}

StreamLineBlock SceneLineBlocks::compute(int b) {
  return layout_.oblique ? off_axes(b) : along_axis(b);
}

// Block b's lines through the line engine, on this rank: its window (the
// lines' cells and their halo) read from the scene file, geometry, image
// formation and its own cells' maps; the median elevation's second pass
// over its own cells.
StreamLineBlock SceneLineBlocks::along_axis(int b) {
  const SlarLineEngine& engine = *engine_;
  StreamLineBlock k = start_line_block(b, layout_.block_lines, lines(), layout_.fail_block, spare_);
  int row0 = 0, rows = 0, col0 = 0, cols = 0;
  // The coherent SAR reads its halo of lines too.
  const auto [r0, r1] = coherent_ ? coherent_->lines_read(k.l0, k.l1) : std::pair{k.l0, k.l1};
  engine.window_for_lines(r0, r1, row0, rows, col0, cols);
  const std::size_t cells = sz(rows) * sz(cols);
  if (cells > z_.size()) {  // lines spaced wider than a cell
    z_.resize(cells);
    cat_.resize(cells);
    ok_.resize(cells);
    window_incidence_.resize(cells);
    window_mask_.resize(cells);
  }
  in_.read(row0, rows, col0, cols, z_.data(), cat_.data(), ok_.data());
  const SceneWindow win{row0, col0, rows, cols, z_.data(), cat_.data(), ok_.data()};
  const SceneMapsWindow maps{row0, col0, rows, cols, window_mask_.data(), window_incidence_.data()};
  // Lines not one per cell: each sample's map values, spilled for pass 1m
  // (which also refines the median elevation over the cells); only the
  // block's own lines (a coherent halo's belong to its neighbours).
  const bool spill = layout_.spill_maps;
  SampleMapRows values{k.l0, nullptr, nullptr};
  if (spill) {
    k.scene_mask.resize(sz(k.l1 - k.l0) * sz(sim_.geometry.samples));
    k.incidence.resize(k.scene_mask.size());
    values = SampleMapRows{k.l0, k.scene_mask.data(), k.incidence.data()};
  }
  if (coherent_) {
    const auto run = [&](int a, int e, bool own, SlarLineProfiles& prof, SlarLineCounts& counts,
                         const LineKeep& keep) {
      if (spill) {
        engine.run(a, e, win, prof, SceneMapsWindow{}, counts, &keep, own ? &values : nullptr);
      } else {
        engine.run(a, e, win, prof, own ? maps : SceneMapsWindow{}, counts, &keep);
      }
    };
    coherent_->run_block(run, k.l0, k.l1, targets_, k.prof, k.counts, k.targets, k.coherent);
    if (!spill) keep_block_maps(win, maps, k);
    return k;
  }
  k.prof.allocate(k.l1 - k.l0, bins(), k.l0);
  k.prof.samples_in_swath = 0;
  // The point targets on the block's lines, found lit or hidden there.
  std::optional<LinePointTargets> on_lines;
  if (targets_) on_lines = targets_->candidates_on_lines(k.l0, k.l1);
  const LineKeep keep{nullptr, nullptr, on_lines ? &*on_lines : nullptr};
  if (spill) {
    engine.run(k.l0, k.l1, win, k.prof, SceneMapsWindow{}, k.counts, on_lines ? &keep : nullptr,
               &values);
  } else {
    engine.run(k.l0, k.l1, win, k.prof, maps, k.counts, on_lines ? &keep : nullptr);
    keep_block_maps(win, maps, k);
  }
  k.targets = on_lines ? targets_->block_result(*on_lines) : BlockTargets{};
  return k;
}

// Block b of a track off the axes (slar_stream_oblique.h): its profile
// rows and counts, and its samples' map values as the block's maps (the
// spilled rasters' rows: lines x samples). The coherent SAR runs its halo
// of lines too (sar_coherent_stream.h), their map values dropped.
StreamLineBlock SceneLineBlocks::off_axes(int b) {
  ObliqueBlockLines& oblique = *oblique_;
  StreamLineBlock k = start_line_block(b, layout_.block_lines, lines(), layout_.fail_block, spare_);
  ObliqueMapValues v{std::move(k.scene_mask), std::move(k.incidence)};
  if (coherent_) {
    ObliqueMapValues halo;
    const auto run = [&](int a, int e, bool own, SlarLineProfiles& prof, SlarLineCounts& counts,
                         const LineKeep& keep) {
      oblique.run(in_, a, e, prof, counts, own ? v : halo, &keep);
    };
    coherent_->run_block(run, k.l0, k.l1, targets_, k.prof, k.counts, k.targets, k.coherent);
    k.scene_mask = std::move(v.mask);
    k.incidence = std::move(v.incidence_deg);
    return k;
  }
  k.prof.allocate(k.l1 - k.l0, bins(), k.l0);
  k.prof.samples_in_swath = 0;
  // The point targets on the block's lines, found lit or hidden there (as
  // along_axis).
  std::optional<LinePointTargets> on_lines;
  if (targets_) on_lines = targets_->candidates_on_lines(k.l0, k.l1);
  const LineKeep keep{nullptr, nullptr, on_lines ? &*on_lines : nullptr};
  oblique.run(in_, k.l0, k.l1, k.prof, k.counts, v, on_lines ? &keep : nullptr);
  k.targets = on_lines ? targets_->block_result(*on_lines) : BlockTargets{};
  k.scene_mask = std::move(v.mask);
  k.incidence = std::move(v.incidence_deg);
  return k;
}

// The block's own cells (its lines' rows or columns, without the halo):
// their scene-grid maps kept for the writers (count rows x cols along y,
// rows x count across), the median elevation's second pass.
void SceneLineBlocks::keep_block_maps(const SceneWindow& win, const SceneMapsWindow& maps,
                                      StreamLineBlock& k) {
  const int c_a = engine_->cell_of_line(k.l0), c_b = engine_->cell_of_line(k.l1 - 1);
  RIS_CHECK(c_a >= 0 && c_b >= 0 && std::abs(c_b - c_a) == k.l1 - k.l0 - 1);
  const int lo = std::min(c_a, c_b), count = k.l1 - k.l0;
  const int cols = win.cols;
  if (layout_.along_y) {
    const std::size_t at = sz(lo - win.row0) * sz(cols);
    const std::size_t n = sz(count) * sz(cols);
    k.scene_mask.assign(maps.mask + at, maps.mask + at + n);
    k.incidence.assign(maps.local_incidence_deg + at, maps.local_incidence_deg + at + n);
    for (std::size_t i = at; i < at + n; ++i)
      if (ok_[i] && std::isfinite(z_[i])) elevation_.refine(z_[i]);
  } else {
    const std::size_t at = sz(lo - win.col0);
    k.scene_mask.resize(sz(win.rows) * sz(count));
    k.incidence.resize(k.scene_mask.size());
    for (int r = 0; r < win.rows; ++r) {
      const std::size_t from = sz(r) * sz(cols) + at, to = sz(r) * sz(count);
      std::copy_n(maps.mask + from, count, k.scene_mask.data() + to);
      std::copy_n(maps.local_incidence_deg + from, count, k.incidence.data() + to);
      for (int c = lo; c < lo + count; ++c) {
        const std::size_t i = sz(r) * sz(cols) + sz(c - win.col0);
        if (ok_[i] && std::isfinite(z_[i])) elevation_.refine(z_[i]);
      }
    }
  }
}

}  // namespace ris::detail
