// The fused SLAR / incoherent SAR run for a track off the grid axes (declared
// in sim/slar_line_kernels.h): terrain sampled bilinearly along each line,
// the shared line geometry and image formation, scene maps scattered per line.
#include <algorithm>
#include <cmath>
#include <limits>

#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"
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
void scatter_line_cells(const Scene& scene, const SlarGeometry& g, int line, const LineScratch& s,
                        double near_m, double far_m, SceneGeometryMaps& maps) {
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
      const std::size_t jj = static_cast<std::size_t>(j);
      scene_map_cell(scene.valid[cell] != 0, s.flags[jj], s.range[jj], s.local_incidence[jj],
                     near_m, far_m, maps.mask[cell], maps.local_incidence_deg[cell]);
    }
  }
}

}  // namespace

// The fused run for any other heading: the stage path's bilinear sampler
// (slar_geometry.cpp fill_line with BilinearSampler: bilinear height and
// slope at half a cell, the nearest cell's category) line by line, then the
// shared line geometry and image formation, and the scene maps scattered
// per line. Only the slope rasters (8 bytes per cell) are whole-scene.
void run_oblique_lines(const Scene& scene, const SlarGeometry& g, const Sigma0Lut& lut,
                       const SlarImagingParams& p, const std::string& radar_file,
                       SlarLineProfiles& prof, SceneGeometryMaps& maps, SlarLineCounts& counts) {
  const SurfaceGradient grad = surface_gradient(scene);
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
#pragma omp for schedule(dynamic, 16)
    for (int line = 0; line < g.lines; ++line) {
      const auto [line_x, line_y] = t.world_from_along_cross(g.line_s_m(line), 0.0);
      for (int j = 0; j < g.samples; ++j) {
        const std::size_t jj = static_cast<std::size_t>(j);
        const double u = g.sample_u_m(j);
        const TerrainSample ts =
            bilinear_terrain_sample(scene, &grad, line_x + u * t.cross_x, line_y + u * t.cross_y);
        std::uint8_t f = 0;
        if (!ts.inside) f |= sample_flag::kUnseen;
        if (ts.inside && !ts.valid) f |= sample_flag::kNoData;
        f |= s.unseen[jj];
        s.flags[jj] = f;
        const bool terrain = ts.inside && ts.valid;
        s.height[jj] = terrain ? ts.height_m : kNaN;
        s.dz_dx[jj] = terrain ? ts.dz_dx : kNaN;
        s.dz_dy[jj] = terrain ? ts.dz_dy : kNaN;
        s.category[jj] = terrain ? ts.category : std::uint16_t{0};
      }
      line_geometry(g, frame, need_incidence, s);
      in_swath += accumulate_line(ctx, g.samples, s, prof, line, local, p.range_window_bins);
      scatter_line_cells(scene, g, line, s, near_m, far_m, maps);
    }
#pragma omp critical(ris_slar_line_counts)
    counts.add(local);
  }
  prof.samples_in_swath += in_swath;
}

}  // namespace ris::detail
