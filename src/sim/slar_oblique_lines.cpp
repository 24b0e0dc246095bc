// The fused SLAR / incoherent SAR run for a track off the grid axes (declared
// in sim/slar_line_kernels.h): terrain sampled bilinearly along each line
// within the scene, the shared line geometry and image formation, and the
// scene maps scattered per block of lines.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ris/geometry/terrain_line.h"
#include "sim/slar_line_kernels.h"

namespace ris::detail {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Lines per block: the block's scene-map values (8 bytes a sample) stay in
// cache while its cells are written, and a block's cells form runs of about
// kBlockLines / |line_dc| cells along each scene row.
constexpr int kBlockLines = 16;

// The t with lo <= a0 + t da <= hi, as a closed interval (empty: first >
// second); da == 0: everything or nothing.
std::pair<double, double> affine_range(double a0, double da, double lo, double hi) {
  constexpr double kAll = 1e300;
  if (da > 0.0) return {(lo - a0) / da, (hi - a0) / da};
  if (da < 0.0) return {(hi - a0) / da, (lo - a0) / da};
  return (a0 >= lo && a0 <= hi) ? std::pair{-kAll, kAll} : std::pair{kAll, -kAll};
}

// [floor(a) - 2, ceil(b) + 2] clamped to [0, n): a candidate range whose two
// cells of margin cover the rounding of the analytic bounds; each candidate
// is then checked exactly.
std::pair<int, int> candidates(std::pair<double, double> ab, int n) {
  const double a = std::clamp(std::floor(ab.first) - 2.0, 0.0, double(n));
  const double b = std::clamp(std::ceil(ab.second) + 3.0, 0.0, double(n));
  return {static_cast<int>(a), static_cast<int>(b)};
}

// One block of lines' scene-map values: per line its span and the values of
// its span's samples (the rest are unseen).
struct BlockMapValues {
  int line0 = 0, lines = 0;
  std::vector<SlarLineSpan> span;
  std::vector<std::size_t> offset;  // of each line's first span sample in `value`
  std::vector<SampleMapValue> value;
  SampleMapValue unseen;

  const SampleMapValue& at(int line, int j) const {
    const auto k = static_cast<std::size_t>(line - line0);
    const SlarLineSpan& sp = span[k];
    if (j < sp.begin || j >= sp.end) return unseen;
    return value[offset[k] + static_cast<std::size_t>(j - sp.begin)];
  }
};

// Writes the scene maps of the cells whose line (cell_sample) is in the
// block: along each scene row the block's cells are one run of columns (the
// line index is affine and monotone in the column), found analytically and
// each cell checked exactly. Every cell belongs to one line, so blocks in
// parallel never write the same cell.
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
    const auto [c_begin, c_end] =
        candidates(affine_range(lbase, f.line_dc, lf_lo, lf_hi), scene.cols);
    // Raw row pointers: byte stores may alias a vector's data pointer.
    const std::size_t row = scene.index(r, 0);
    const std::uint8_t* const valid = scene.valid.data() + row;
    std::uint8_t* const mask = maps.mask.data() + row;
    float* const incidence = maps.local_incidence_deg.data() + row;
    for (int c = c_begin; c < c_end; ++c) {
      int line = 0, j = 0;
      if (!nearest_index(f.line_f(lbase, c), f.lines, line) || line < l0 || line >= l1) continue;
      // Cells outside the swath keep their initial mask.
      if (!nearest_index(f.sample_f(sbase, c), f.samples, j)) continue;
      scene_map_from_sample(valid[c] != 0, b.at(line, j), mask[c], incidence[c]);
    }
  }
}

}  // namespace

// The fused run for any other heading: per line, the samples within the
// scene (slar_line_span) from the line sampler (ris/geometry/terrain_line.h),
// the shared line geometry and image formation over those samples only, then
// per block of lines the scene maps. The stage path samples and scans the
// same spans (slar_geometry.cpp fill_oblique_line) and assigns cells by the
// same rule (cell_sample), so the bytes agree. Only the texels (16 bytes per
// cell) are whole-scene.
void run_oblique_lines(const Scene& scene, const SlarGeometry& g, const Sigma0Lut& lut,
                       const SlarImagingParams& p, const std::string& radar_file,
                       SlarLineProfiles& prof, SceneGeometryMaps& maps, SlarLineCounts& counts) {
  const TerrainTexels tex = terrain_texels(scene);
  const CellSampleFrame frame = cell_sample_frame(scene, g);
  const TwoWayGainTable gain2(p.elevation_gain, p.peak_gain, radar_file);
  const detail::SlarElementContext ctx = element_context(p, gain2, lut, prof.bins);
  const Track& t = g.track;
  const LineLookFrame look{g.altitude_m, t.cross_x, t.cross_y, g.line_spacing_m * g.sample_step_m};
  const bool need_incidence = !gain2.uniform();
  const double near_m = p.range.near_m, far_m = p.range.far_m();
  // Every cell starts outside the swath; the blocks overwrite theirs. Raw
  // pointers: a byte store may alias a vector's own data pointer, which
  // would otherwise be reloaded per cell.
  const auto n_cells = static_cast<std::int64_t>(scene.size());
  std::uint8_t* const mask = maps.mask.data();
  float* const incidence = maps.local_incidence_deg.data();
  const std::uint8_t* const valid = scene.valid.data();
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n_cells; ++i) {
    mask[i] = (valid[i] ? 0 : scene_flag::kNoData) | scene_flag::kOutsideSwath;
    incidence[i] = kNaN;
  }
  const int blocks = (g.lines + kBlockLines - 1) / kBlockLines;
  std::int64_t in_swath = 0;
#pragma omp parallel reduction(+ : in_swath)
  {
    LineScratch s(g, prof.bins);
    SlarLineCounts local;
    // Each line's span as a line of its own (line_geometry and
    // accumulate_line run over samples 0..n of the scratch): its first
    // sample's u and count.
    SlarGeometry span_layout = g;
    const std::vector<float> u_all = s.u;
    BlockMapValues b;
    b.unseen = scene_map_sample(sample_flag::kUnseen, kNaN, kNaN, near_m, far_m);
    b.value.reserve(static_cast<std::size_t>(kBlockLines) * static_cast<std::size_t>(g.samples));
#pragma omp for schedule(dynamic, 1)
    for (int block = 0; block < blocks; ++block) {
      b.line0 = block * kBlockLines;
      b.lines = std::min(kBlockLines, g.lines - b.line0);
      b.span.clear();
      b.offset.clear();
      b.value.clear();
      for (int line = b.line0; line < b.line0 + b.lines; ++line) {
        const SlarLineSpan span = slar_line_span(scene, g, line);
        const int n = span.end - span.begin;
        const auto first = static_cast<std::ptrdiff_t>(span.begin);
        sample_terrain_line(
            tex, span.grid, span.begin, span.end,
            {s.height.data(), s.dz_dx.data(), s.dz_dy.data(), s.category.data(), s.flags.data()});
        std::copy(u_all.begin() + first, u_all.begin() + first + n, s.u.begin());
        span_layout.samples = n;
        span_layout.first_sample_u_m = g.sample_u_m(span.begin);
        line_geometry(span_layout, look, need_incidence, s);
        in_swath += accumulate_line(ctx, n, s, prof, line, local, p.range_window_bins, span.begin);
        b.span.push_back(span);
        const std::size_t offset = b.value.size();
        b.offset.push_back(offset);
        b.value.resize(offset + static_cast<std::size_t>(n));
        SampleMapValue* const value = b.value.data() + offset;
        for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {
          value[k] = scene_map_sample(s.flags[k], s.range[k], s.local_incidence[k], near_m, far_m);
        }
      }
      scatter_block(scene, frame, b, maps);
    }
#pragma omp critical(ris_slar_line_counts)
    counts.add(local);
  }
  prof.samples_in_swath += in_swath;
}

}  // namespace ris::detail
