// The fused SLAR / incoherent SAR run for a track off the grid axes (declared
// in sim/engine/slar_line_stages.h): terrain sampled bilinearly along each line
// within the scene, the shared line geometry and image formation, and the
// scene maps scattered per block of lines.
#include <algorithm>
#include <cmath>
#include <limits>
#include <variant>
#include <vector>

#include "kernels/gather/oblique_scatter_kernels.h"
#include "ris/geometry/terrain_line.h"
#include "sim/sources/slar_oblique_lines.h"

namespace ris::detail {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Lines per block: the block's scene-map values (8 bytes a sample) stay in
// cache while its cells are written, and a block's cells form runs of about
// kBlockLines / |line_dc| cells along each scene row.
constexpr int kBlockLines = 16;

// Marks the cells of each row outside its swath_cells (the blocks write all
// the others).
void fill_outside_swath(const Scene& scene, const CellSampleFrame& f, SceneGeometryMaps& maps) {
  // Raw pointers: a byte store may alias a vector's own data pointer, which
  // would otherwise be reloaded per cell.
  std::uint8_t* const mask = maps.mask.data();
  float* const incidence = maps.local_incidence_deg.data();
  const std::uint8_t* const valid = scene.valid.data();
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    const auto [c_begin, c_end] = swath_cells(scene, f, r);
    const std::size_t row = scene.index(r, 0);
    const auto outside = [&](int c0, int c1) {
      mark_outside_swath(valid + row, mask + row, incidence + row, static_cast<std::size_t>(c0),
                         static_cast<std::size_t>(c1));
    };
    outside(0, c_begin);
    outside(c_end, scene.cols);
  }
}

// One block of lines' scene-map values, dense: row k (line line0 + k) holds
// samples [j_lo - 1, j_hi] of the line, where [j_lo, j_hi) covers every
// line's span; samples outside a line's span (and the two guard columns,
// which any sample index beyond the covered range is clamped to) are unseen.
// Dense, so that the scatter looks a cell's value up without a branch.
struct BlockMapValues {
  int line0 = 0, lines = 0;
  int j_lo = 0, j_hi = 0;          // samples covered
  int width = 0;                   // j_hi - j_lo + 2
  std::vector<std::int32_t> mask;  // scene_flag bits; 32-bit for AVX2 gathers
  std::vector<float> incidence_deg;
  SampleMapValue unseen;

  // Sizes the block for spans within [lo, hi) (not filled: set_span
  // writes each line's unseen samples, map_values the rest).
  void reset(int first_line, int n_lines, int lo, int hi) {
    line0 = first_line;
    lines = n_lines;
    j_lo = lo;
    j_hi = std::max(lo, hi);
    width = j_hi - j_lo + 2;
    const std::size_t n = static_cast<std::size_t>(lines) * static_cast<std::size_t>(width);
    if (mask.size() < n) {
      mask.resize(n);
      incidence_deg.resize(n);
    }
  }
  // Marks the samples of `line` outside its span [begin, end) unseen, the
  // guard columns included (the span's own values come from map_values).
  void set_span(int line, int begin, int end) {
    const auto fill = [&](std::size_t from, std::size_t to) {
      std::fill(mask.begin() + static_cast<std::ptrdiff_t>(from),
                mask.begin() + static_cast<std::ptrdiff_t>(to), std::int32_t{unseen.mask});
      std::fill(incidence_deg.begin() + static_cast<std::ptrdiff_t>(from),
                incidence_deg.begin() + static_cast<std::ptrdiff_t>(to),
                unseen.local_incidence_deg);
    };
    const std::size_t row =
        static_cast<std::size_t>(line - line0) * static_cast<std::size_t>(width);
    if (begin >= end) {
      fill(row, row + static_cast<std::size_t>(width));
      return;
    }
    fill(row, index(line, begin));
    fill(index(line, end - 1) + 1, row + static_cast<std::size_t>(width));
  }
  // Index of (line, j) for a line of the block and any j (clamped to the
  // guard columns).
  std::size_t index(int line, int j) const {
    const int jc = j < j_lo - 1 ? j_lo - 1 : (j > j_hi ? j_hi : j);
    return static_cast<std::size_t>(line - line0) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(jc - (j_lo - 1));
  }
};

// Writes the scene maps of the cells whose line (cell_sample) is in the
// block: along each scene row the block's cells are one run of columns (the
// line and sample indices are affine and monotone in the column), found
// analytically with a margin and its ends then checked exactly. Every cell
// belongs to one line, so blocks in parallel never write the same cell.
void scatter_block(const Scene& scene, const CellSampleFrame& f, const BlockMapValues& b,
                   SceneGeometryMaps& maps) {
  const int l0 = b.line0, l1 = b.line0 + b.lines;
  // The block's lines round from line_f in [l0 - 1/2, l1 - 1/2); over a row
  // line_f spans base + [c_lo, c_hi].
  const double lf_lo = l0 - 0.5, lf_hi = l1 - 0.5;
  const double c_lo = std::min(0.0, (scene.cols - 1) * f.line_dc);
  const double c_hi = std::max(0.0, (scene.cols - 1) * f.line_dc);
  const auto [r_begin, r_end] =
      candidates(affine_range(f.line0, f.line_dr, lf_lo - c_hi, lf_hi - c_lo), scene.rows);
  for (int r = r_begin; r < r_end; ++r) {
    const double lbase = f.line_row_base(r), sbase = f.sample_row_base(r);
    auto [c_begin, c_end] = candidates(affine_range(lbase, f.line_dc, lf_lo, lf_hi), scene.cols);
    // The cells that take a line of this block and a sample (cell_sample's
    // rule): an interval of the candidates, since both indices are monotone
    // in the column; trim its ends exactly.
    trim(c_begin, c_end, [&](int c) {
      int line = 0, j = 0;
      return nearest_index(f.line_f(lbase, c), f.lines, line) && line >= l0 && line < l1 &&
             nearest_index(f.sample_f(sbase, c), f.samples, j);
    });
    if (c_begin == c_end) continue;
    const std::size_t row = scene.index(r, 0);
    const kernels::BlockMapView view{
        b.mask.data(), b.incidence_deg.data(), b.line0, b.j_lo - 1, b.j_hi, b.width};
    kernels::scatter_run(lbase, f.line_dc, sbase, f.sample_dc, c_begin, c_end, view,
                         scene.valid.data() + row, maps.mask.data() + row,
                         maps.local_incidence_deg.data() + row);
  }
}

// ---- The oblique line source ---------------------------------------------
// Per line, the samples within the scene (slar_line_span) from the line
// sampler (ris/geometry/terrain_line.h), each span as a line of its own
// (the stages run over samples 0..n of the scratch); per block of lines, the
// scene maps scattered into the grid.

// What every oblique source of a run reads.
struct ObliqueRun {
  const Scene& scene;
  const SlarGeometry& g;
  const TerrainTexels& tex;
  const CellSampleFrame& frame;
  SceneGeometryMaps& maps;
  double near_m, far_m;
};

// One thread's buffers: the block's spans and map values, the span's layout.
struct ObliqueThreadState {
  const ObliqueRun& run;
  SlarGeometry span_layout;
  std::vector<float> u_all;  // every sample's u (the scratch's u is per span)
  BlockMapValues b;
  std::vector<SlarLineSpan> spans;
};

struct ObliqueSource {
  ObliqueThreadState& t;

  LineSpan load(int line, LineScratch& s) {
    const SlarLineSpan& span = t.spans[static_cast<std::size_t>(line - t.b.line0)];
    return load_oblique_span(
        t.run.g, span, t.u_all, t.span_layout, s, [&](const SlarLineSpan& sp, LineScratch& out) {
          sample_terrain_line(t.run.tex, sp.grid, sp.begin, sp.end,
                              {out.height.data(), out.dz_dx.data(), out.dz_dy.data(),
                               out.category.data(), out.flags.data()});
        });
  }
  void store_maps(int line, const LineSpan& span, const LineScratch& s) {
    t.b.set_span(line, span.first, span.first + span.n);
    if (span.n <= 0) return;
    const std::size_t k0 = t.b.index(line, span.first);
    kernels::map_values(span.n, s.flags.data(), s.range.data(), s.local_incidence.data(),
                        t.run.near_m, t.run.far_m, t.b.mask.data() + k0,
                        t.b.incidence_deg.data() + k0);
  }
  void finish_block() const { scatter_block(t.run.scene, t.run.frame, t.b, t.run.maps); }
};

struct ObliqueThreadSource {
  ObliqueThreadState t;

  // The block's spans, and its map values sized to cover them.
  std::variant<ObliqueSource> block(int b0, int b1) {
    const SlarGeometry& g = t.run.g;
    int j_lo = g.samples, j_hi = 0;
    for (int line = b0; line < b1; ++line) {
      const SlarLineSpan& span = t.spans[static_cast<std::size_t>(line - b0)] =
          slar_line_span(t.run.scene, g, line);
      if (span.begin < span.end) {
        j_lo = std::min(j_lo, span.begin);
        j_hi = std::max(j_hi, span.end);
      }
    }
    t.b.reset(b0, b1 - b0, j_lo, j_hi);
    return ObliqueSource{t};
  }
};

}  // namespace

std::pair<double, double> affine_range(double a0, double da, double lo, double hi) {
  constexpr double kAll = 1e300;
  if (da > 0.0) return {(lo - a0) / da, (hi - a0) / da};
  if (da < 0.0) return {(hi - a0) / da, (lo - a0) / da};
  return (a0 >= lo && a0 <= hi) ? std::pair{-kAll, kAll} : std::pair{kAll, -kAll};
}

std::pair<int, int> candidates(std::pair<double, double> ab, int n) {
  const double a = std::clamp(std::floor(ab.first) - 1.0, 0.0, double(n));
  const double b = std::clamp(std::ceil(ab.second) + 2.0, 0.0, double(n));
  return {static_cast<int>(a), static_cast<int>(std::max(a, b))};
}

std::pair<int, int> swath_cells(const Scene& scene, const CellSampleFrame& f, int r) {
  const double lbase = f.line_row_base(r), sbase = f.sample_row_base(r);
  const auto [l_lo, l_hi] = affine_range(lbase, f.line_dc, -0.5, f.lines - 0.5);
  const auto [s_lo, s_hi] = affine_range(sbase, f.sample_dc, -0.5, f.samples - 0.5);
  auto [c_begin, c_end] = candidates({std::max(l_lo, s_lo), std::min(l_hi, s_hi)}, scene.cols);
  trim(c_begin, c_end, [&](int c) {
    int line = 0, j = 0;
    return nearest_index(f.line_f(lbase, c), f.lines, line) &&
           nearest_index(f.sample_f(sbase, c), f.samples, j);
  });
  return {c_begin, c_end};
}

SampleMapValue unseen_map_value(double near_m, double far_m) {
  return scene_map_sample(sample_flag::kUnseen, kNaN, kNaN, near_m, far_m);
}

ObliqueStages::ObliqueStages(const SlarGeometry& g, const Sigma0Lut& lut,
                             const SlarImagingParams& p, const std::string& radar_file, int bins,
                             const LineKeep* keep, std::span<const ExtraChannel> channels)
    : gain2_(p.elevation_gain, p.peak_gain, radar_file),
      ctx_(element_context(p, gain2_, lut, bins)),
      stages_{ctx_,
              LineLookFrame{g.altitude_m, g.track.cross_x, g.track.cross_y,
                            g.line_spacing_m * g.sample_step_m},
              !gain2_.uniform() || (keep && keep->geometry) || channels_need_incidence(channels),
              p.range_window_bins,
              keep,
              channels} {}

// The fused run for any other heading, through the line engine with the
// oblique source. The stage path samples and scans the same spans
// (slar_geometry.cpp fill_oblique_line) and assigns cells by the same rule
// (cell_sample), so the bytes agree. Only the texels (16 bytes per cell)
// are whole-scene.
void run_oblique_lines(const Scene& scene, const SlarGeometry& g, const Sigma0Lut& lut,
                       const SlarImagingParams& p, const std::string& radar_file,
                       SlarLineProfiles& prof, SceneGeometryMaps& maps, SlarLineCounts& counts,
                       const LineKeep* keep, std::span<const ExtraChannel> channels) {
  const TerrainTexels tex = terrain_texels(scene);
  const CellSampleFrame frame = cell_sample_frame(scene, g);
  const ObliqueStages os(g, lut, p, radar_file, prof.bins, keep, channels);
  const LineStages& stages = os.stages();
  const ObliqueRun run{scene, g, tex, frame, maps, p.range.near_m, p.range.far_m()};
  // Each row's cells outside the swath here, the others by the blocks
  // (each cell by one: not written twice).
  fill_outside_swath(scene, frame, maps);
  run_line_blocks(g, stages, 0, g.lines, kBlockLines, prof, counts, [&](LineScratch& s) {
    ObliqueThreadSource ts{{run, g, s.u, {}, std::vector<SlarLineSpan>(kBlockLines)}};
    ts.t.b.unseen = unseen_map_value(run.near_m, run.far_m);
    return ts;
  });
}

}  // namespace ris::detail
