#include "sim/stream/slar_stream_oblique.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <variant>

#include "kernels/gather/oblique_scatter_kernels.h"
#include "ris/util/error.h"
#include "sim/engine/texel_window.h"

namespace ris::detail {

namespace {

// The engine's lines per thread block (as run_oblique_lines).
constexpr int kEngineLines = 16;
// A window of the scene covers up to this many lines of a block and samples
// of each: at 30-60 degrees about (256 + 128) x (128 + 128) cells, 1-2 MB
// with the texels, whatever the block's or the scene's size.
constexpr int kGroupLines = 128;
constexpr int kSegmentSamples = 512;
// A tile of pass 1m: its cells take up to ~(tile + tile) lines and twice as
// many samples (half-cell steps), read back as one window.
constexpr int kTileCols = 256;

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

// What a block's sources read: its spans, its sampled terrain, and where its
// samples' map values go.
struct BlockView {
  const SlarGeometry& g;
  const std::vector<float>& u_all;
  const std::vector<SlarLineSpan>& spans;
  int l0 = 0;
  const float *height, *dz_dx, *dz_dy;
  const std::uint16_t* category;
  const std::uint8_t* flags;
  ObliqueMapValues& maps;
  double near_m, far_m;
};

struct StreamThreadState {
  const BlockView& v;
  SlarGeometry span_layout;
  std::vector<std::int32_t> mask;  // a span's mask values (map_values' type)
};

// A line's terrain from the block's sampled terrain; its samples' map values
// into the block's rows.
struct StreamObliqueSource {
  StreamThreadState& t;

  LineSpan load(int line, LineScratch& s) {
    const BlockView& v = t.v;
    const std::size_t row = sz(line - v.l0) * sz(v.g.samples);
    return load_oblique_span(v.g, v.spans[sz(line - v.l0)], v.u_all, t.span_layout, s,
                             [&](const SlarLineSpan& sp, LineScratch& out) {
                               const std::size_t at = row + sz(sp.begin);
                               const std::size_t n = sz(sp.end - sp.begin);
                               std::copy_n(v.height + at, n, out.height.begin());
                               std::copy_n(v.dz_dx + at, n, out.dz_dx.begin());
                               std::copy_n(v.dz_dy + at, n, out.dz_dy.begin());
                               std::copy_n(v.category + at, n, out.category.begin());
                               std::copy_n(v.flags + at, n, out.flags.begin());
                             });
  }
  void store_maps(int line, const LineSpan& span, const LineScratch& s) {
    if (span.n <= 0) return;
    const BlockView& v = t.v;
    const std::size_t at = sz(line - v.l0) * sz(v.g.samples) + sz(span.first);
    kernels::map_values(span.n, s.flags.data(), s.range.data(), s.local_incidence.data(), v.near_m,
                        v.far_m, t.mask.data(), v.maps.incidence_deg.data() + at);
    for (int k = 0; k < span.n; ++k)
      v.maps.mask[at + sz(k)] = static_cast<std::uint8_t>(t.mask[sz(k)]);
  }
  void finish_block() const {}
};

struct StreamThreadSource {
  StreamThreadState t;
  std::variant<StreamObliqueSource> block(int, int) { return StreamObliqueSource{t}; }
};

}  // namespace

ObliqueBlockLines::ObliqueBlockLines(const Scene& grid, const SlarGeometry& g, const Sigma0Lut& lut,
                                     const SlarImagingParams& p, const std::string& radar_file,
                                     int bins)
    : grid_(grid),
      g_(g),
      stages_(g, lut, p, radar_file, bins, nullptr),
      near_m_(p.range.near_m),
      far_m_(p.range.far_m()) {
  u_all_.resize(sz(g.samples));
  for (int j = 0; j < g.samples; ++j) u_all_[sz(j)] = float(g.sample_u_m(j));
}

void ObliqueBlockLines::run(const SceneStreamReader& in, int l0, int l1, SlarLineProfiles& prof,
                            SlarLineCounts& counts, ObliqueMapValues& maps, const LineKeep* keep) {
  // Point targets, and the coherent SAR's element power and slant range;
  // not the kept geometry (the in-memory run's: it would change
  // need_incidence, which the stages were made without).
  RIS_CHECK(!keep || !keep->geometry);
  const std::size_t n = sz(l1 - l0) * sz(g_.samples);
  spans_.resize(sz(l1 - l0));
  for (int line = l0; line < l1; ++line) spans_[sz(line - l0)] = slar_line_span(grid_, g_, line);
  height_.resize(n);
  dz_dx_.resize(n);
  dz_dy_.resize(n);
  category_.resize(n);
  flags_.resize(n);
  sample_block(in, l0, l1);
  // Unseen, but where a line's span writes its values.
  const SampleMapValue unseen = unseen_map_value(near_m_, far_m_);
  maps.mask.assign(n, static_cast<std::uint8_t>(unseen.mask));
  maps.incidence_deg.assign(n, unseen.local_incidence_deg);
  const BlockView v{g_,
                    u_all_,
                    spans_,
                    l0,
                    height_.data(),
                    dz_dx_.data(),
                    dz_dy_.data(),
                    category_.data(),
                    flags_.data(),
                    maps,
                    near_m_,
                    far_m_};
  LineStages stages = stages_.stages();
  stages.keep = keep;
  run_line_blocks(g_, stages, l0, l1, kEngineLines, prof, counts, [&](LineScratch&) {
    return StreamThreadSource{{v, g_, std::vector<std::int32_t>(sz(g_.samples))}};
  });
}

// The block's lines in groups, each group's samples in segments: one window
// of the scene per segment.
void ObliqueBlockLines::sample_block(const SceneStreamReader& in, int l0, int l1) {
  const int n = l1 - l0;
  for (int k0 = 0; k0 < n; k0 += kGroupLines) {
    const int k1 = std::min(n, k0 + kGroupLines);
    int lo = g_.samples, hi = 0;
    for (int k = k0; k < k1; ++k) {
      const SlarLineSpan& s = spans_[sz(k)];
      if (s.begin >= s.end) continue;
      lo = std::min(lo, s.begin);
      hi = std::max(hi, s.end);
    }
    for (int a = lo; a < hi; a += kSegmentSamples)
      sample_segment(in, k0, k1, a, std::min(hi, a + kSegmentSamples));
  }
}

// Lines k0..k1 (block-relative), samples [a, b): the cells they touch (a
// line's samples are on a straight line, so its first and last sample bound
// them), read as one window.
void ObliqueBlockLines::sample_segment(const SceneStreamReader& in, int k0, int k1, int a, int b) {
  CellBox box;
  for (int k = k0; k < k1; ++k) {
    const SlarLineSpan& s = spans_[sz(k)];
    const int js = std::max(a, s.begin), je = std::min(b, s.end);
    if (js >= je) continue;
    box = box.united(sample_cells(grid_, s.grid, js)).united(sample_cells(grid_, s.grid, je - 1));
  }
  if (box.empty()) return;
  const TexelWindow tw = read_texel_window(in, box, window_);
#pragma omp parallel for schedule(dynamic, 4)
  for (int k = k0; k < k1; ++k) {
    const SlarLineSpan& s = spans_[sz(k)];
    const int js = std::max(a, s.begin), je = std::min(b, s.end);
    if (js >= je) continue;
    const std::size_t at = sz(k) * sz(g_.samples) + sz(js);
    sample_from_window(tw, grid_, s.grid, js, je,
                       {height_.data() + at, dz_dx_.data() + at, dz_dy_.data() + at,
                        category_.data() + at, flags_.data() + at});
  }
}

ObliqueSceneMaps::ObliqueSceneMaps(const Scene& grid, const SlarGeometry& g, double near_m,
                                   double far_m)
    : grid_(grid), frame_(cell_sample_frame(grid, g)), unseen_(unseen_map_value(near_m, far_m)) {}

void ObliqueSceneMaps::rows(int r0, int rows, const std::uint8_t* valid,
                            const SpilledValuesReader& read, std::uint8_t* mask,
                            float* incidence_deg) {
  swath_.resize(sz(rows));
  for (int i = 0; i < rows; ++i) swath_[sz(i)] = swath_cells(grid_, frame_, r0 + i);
  for (int c0 = 0; c0 < grid_.cols; c0 += kTileCols)
    tile(r0, rows, c0, std::min(grid_.cols, c0 + kTileCols), valid, read, mask, incidence_deg);
}

// Cells [c0, c1) of the band's rows: those outside the swath marked, the
// others from the window of lines and samples they take (with a guard
// column each side, unseen, as scatter_block's block values have).
void ObliqueSceneMaps::tile(int r0, int rows, int c0, int c1, const std::uint8_t* valid,
                            const SpilledValuesReader& read, std::uint8_t* mask,
                            float* incidence_deg) {
  const CellSampleFrame& f = frame_;
  int l_lo = std::numeric_limits<int>::max(), l_hi = -1;
  int j_lo = std::numeric_limits<int>::max(), j_hi = -1;
  for (int i = 0; i < rows; ++i) {
    const std::size_t row = sz(i) * sz(grid_.cols);
    const int cb = std::clamp(swath_[sz(i)].first, c0, c1);
    const int ce = std::clamp(swath_[sz(i)].second, cb, c1);
    mark_outside_swath(valid + row, mask + row, incidence_deg + row, sz(c0), sz(cb));
    mark_outside_swath(valid + row, mask + row, incidence_deg + row, sz(ce), sz(c1));
    if (cb >= ce) continue;
    // Both indices are monotone along the row: its run's ends bound them.
    const double lbase = f.line_row_base(r0 + i), sbase = f.sample_row_base(r0 + i);
    for (int c : {cb, ce - 1}) {
      int line = 0, j = 0;
      const bool takes = nearest_index(f.line_f(lbase, c), f.lines, line) &&
                         nearest_index(f.sample_f(sbase, c), f.samples, j);
      RIS_CHECK(takes);
      l_lo = std::min(l_lo, line);
      l_hi = std::max(l_hi, line);
      j_lo = std::min(j_lo, j);
      j_hi = std::max(j_hi, j);
    }
  }
  if (l_hi < 0) return;
  const int nl = l_hi - l_lo + 1, nj = j_hi - j_lo + 1, width = nj + 2;
  read_mask_.resize(sz(nl) * sz(nj));
  view_mask_.resize(sz(nl) * sz(width));
  view_incidence_.resize(sz(nl) * sz(width));
  // Read into the view's rows, then spread out past the guard columns.
  read(l_lo, nl, j_lo, nj, read_mask_.data(), view_incidence_.data());
  for (int k = nl - 1; k >= 0; --k) {
    const std::size_t from = sz(k) * sz(nj), to = sz(k) * sz(width);
    std::copy_backward(view_incidence_.begin() + std::ptrdiff_t(from),
                       view_incidence_.begin() + std::ptrdiff_t(from + sz(nj)),
                       view_incidence_.begin() + std::ptrdiff_t(to + 1 + sz(nj)));
    for (int j = 0; j < nj; ++j) view_mask_[to + 1 + sz(j)] = read_mask_[from + sz(j)];
    view_mask_[to] = view_mask_[to + sz(width) - 1] = unseen_.mask;
    view_incidence_[to] = view_incidence_[to + sz(width) - 1] = unseen_.local_incidence_deg;
  }
  const kernels::BlockMapView view{
      view_mask_.data(), view_incidence_.data(), l_lo, j_lo - 1, j_hi + 1, width};
  for (int i = 0; i < rows; ++i) {
    const int cb = std::clamp(swath_[sz(i)].first, c0, c1);
    const int ce = std::clamp(swath_[sz(i)].second, cb, c1);
    if (cb >= ce) continue;
    const std::size_t row = sz(i) * sz(grid_.cols);
    kernels::scatter_run(f.line_row_base(r0 + i), f.line_dc, f.sample_row_base(r0 + i), f.sample_dc,
                         cb, ce, view, valid + row, mask + row, incidence_deg + row);
  }
}

}  // namespace ris::detail
