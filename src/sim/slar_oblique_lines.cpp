// The fused SLAR / incoherent SAR run for a track off the grid axes (declared
// in sim/slar_line_kernels.h): terrain sampled bilinearly along each line
// within the scene, the shared line geometry and image formation, scene maps
// scattered per line.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ris/geometry/terrain_line.h"
#include "sim/slar_line_kernels.h"

namespace ris::detail {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Writes the scene-map cells whose nearest line is `line` (scene_geometry_maps'
// rule, scene_cell_sample) from the line's samples. The cells of one line
// form a strip across the grid: scanned row by row (or column by column,
// whichever axis the strip crosses more steeply) over the few cells where the
// along-track distance is within a line of it, each checked exactly. Every
// cell belongs to one line, so lines in parallel never write the same cell.
// The scratch holds samples [begin, end) of the line, from index 0.
void scatter_line_cells(const Scene& scene, const SlarGeometry& g, int line, int begin, int end,
                        const LineScratch& s, double near_m, double far_m,
                        SceneGeometryMaps& maps) {
  const Track& t = g.track;
  const double ds = g.line_spacing_m;
  const double s_lo = line * ds, s_hi = (line + 1) * ds;
  // Along-track distance per column (x east) and per row (y north = row - 1).
  const double ds_dc = t.along_x * scene.dx_m, ds_dr = -t.along_y * scene.dy_m;
  const bool by_rows = std::abs(ds_dc) >= std::abs(ds_dr);
  const int outer_n = by_rows ? scene.rows : scene.cols;
  const int inner_n = by_rows ? scene.cols : scene.rows;
  const double step = by_rows ? ds_dc : ds_dr;
  // The outer range where the band meets the grid: the band's inner
  // coordinate moves linearly with o (rate per outer step); a margin of two
  // covers rounding, and each candidate cell is checked exactly below.
  const auto band_at = [&](int o, double& ia, double& ib) {
    const int r0 = by_rows ? o : 0, c0 = by_rows ? 0 : o;
    const auto [x0, y0] = scene.cell_centre(r0, c0);
    const double s0 = t.along_cross(x0, y0).first;
    ia = (s_lo - s0) / step;
    ib = (s_hi - s0) / step;
  };
  double a0 = 0.0, b0 = 0.0, a1 = 0.0, b1 = 0.0;
  band_at(0, a0, b0);
  band_at(1, a1, b1);
  const double rate = a1 - a0;  // inner cells per outer step
  const double lo0 = std::min(a0, b0) - 2.0, hi0 = std::max(a0, b0) + 2.0;
  double first = 0.0, last = outer_n;
  if (rate > 0.0) {
    first = std::floor(-hi0 / rate) - 2.0;
    last = std::ceil((inner_n - lo0) / rate) + 2.0;
  } else if (rate < 0.0) {
    first = std::floor((inner_n - lo0) / rate) - 2.0;
    last = std::ceil(-hi0 / rate) + 2.0;
  }
  const int o_begin = static_cast<int>(std::clamp(first, 0.0, double(outer_n)));
  const int o_end = static_cast<int>(std::clamp(last, 0.0, double(outer_n)));
  for (int o = o_begin; o < o_end; ++o) {
    const int r0 = by_rows ? o : 0, c0 = by_rows ? 0 : o;
    const auto [x0, y0] = scene.cell_centre(r0, c0);
    const double s0 = t.along_cross(x0, y0).first;
    const double ia = (s_lo - s0) / step, ib = (s_hi - s0) / step;
    const int lo = std::max(0, static_cast<int>(std::floor(std::min(ia, ib))) - 1);
    const int hi = std::min(inner_n - 1, static_cast<int>(std::ceil(std::max(ia, ib))) + 1);
    for (int k = lo; k <= hi; ++k) {
      const int r = by_rows ? o : k, c = by_rows ? k : o;
      int cell_line = 0, j = 0;
      // Cells outside the swath keep their initial mask.
      if (!scene_cell_sample(scene, g, r, c, cell_line, j) || cell_line != line) continue;
      const std::size_t cell = scene.index(r, c);
      if (j < begin || j >= end) {  // an unseen sample (beyond the scene's edge)
        scene_map_cell(scene.valid[cell] != 0, sample_flag::kUnseen, kNaN, kNaN, near_m, far_m,
                       maps.mask[cell], maps.local_incidence_deg[cell]);
        continue;
      }
      const auto jj = static_cast<std::size_t>(j - begin);
      scene_map_cell(scene.valid[cell] != 0, s.flags[jj], s.range[jj], s.local_incidence[jj],
                     near_m, far_m, maps.mask[cell], maps.local_incidence_deg[cell]);
    }
  }
}

}  // namespace

// The fused run for any other heading: per line, the samples within the
// scene (slar_line_span) from the line sampler (ris/geometry/terrain_line.h),
// the shared line geometry and image formation over those samples only,
// and the scene maps scattered per line. The stage path samples and scans
// the same span (slar_geometry.cpp fill_oblique_line), so the bytes agree.
// Only the texels (16 bytes per cell) are whole-scene.
void run_oblique_lines(const Scene& scene, const SlarGeometry& g, const Sigma0Lut& lut,
                       const SlarImagingParams& p, const std::string& radar_file,
                       SlarLineProfiles& prof, SceneGeometryMaps& maps, SlarLineCounts& counts) {
  const TerrainTexels tex = terrain_texels(scene);
  const TwoWayGainTable gain2(p.elevation_gain, p.peak_gain, radar_file);
  const detail::SlarElementContext ctx = element_context(p, gain2, lut, prof.bins);
  const Track& t = g.track;
  const LineLookFrame frame{g.altitude_m, t.cross_x, t.cross_y, g.line_spacing_m * g.sample_step_m};
  const bool need_incidence = !gain2.uniform();
  const double near_m = p.range.near_m, far_m = p.range.far_m();
  const auto n_cells = static_cast<std::int64_t>(scene.size());
#pragma omp parallel for schedule(static)
  for (std::int64_t i = 0; i < n_cells; ++i) {
    const auto k = static_cast<std::size_t>(i);
    maps.mask[k] = (scene.valid[k] ? 0 : scene_flag::kNoData) | scene_flag::kOutsideSwath;
    maps.local_incidence_deg[k] = kNaN;
  }
  std::int64_t in_swath = 0;
#pragma omp parallel reduction(+ : in_swath)
  {
    LineScratch s(g, prof.bins);
    SlarLineCounts local;
    // The line's span as a line of its own (line_geometry and accumulate_line
    // run over samples 0..n of the scratch): its first sample's u and count.
    SlarGeometry span_layout = g;
    const std::vector<float> u_all = s.u;
#pragma omp for schedule(dynamic, 16)
    for (int line = 0; line < g.lines; ++line) {
      const SlarLineSpan span = slar_line_span(scene, g, line);
      const int n = span.end - span.begin;
      const auto b = static_cast<std::size_t>(span.begin);
      sample_terrain_line(
          tex, span.grid, span.begin, span.end,
          {s.height.data(), s.dz_dx.data(), s.dz_dy.data(), s.category.data(), s.flags.data()});
      std::copy(u_all.begin() + static_cast<std::ptrdiff_t>(b),
                u_all.begin() + static_cast<std::ptrdiff_t>(b) + n, s.u.begin());
      span_layout.samples = n;
      span_layout.first_sample_u_m = g.sample_u_m(span.begin);
      line_geometry(span_layout, frame, need_incidence, s);
      in_swath += accumulate_line(ctx, n, s, prof, line, local, p.range_window_bins);
      scatter_line_cells(scene, g, line, span.begin, span.end, s, near_m, far_m, maps);
    }
#pragma omp critical(ris_slar_line_counts)
    counts.add(local);
  }
  prof.samples_in_swath += in_swath;
}

}  // namespace ris::detail
