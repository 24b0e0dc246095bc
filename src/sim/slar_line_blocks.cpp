#include "ris/sim/slar_line_blocks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "image/slar_element.h"
#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

bool nearly(double a, double b) {
  return std::abs(a - b) < 1e-9;
}

// One thread's line scratch, allocated once per run() call and thread.
struct LineScratch {
  std::vector<float> u, height, dz_dx, dz_dy, range, incidence, local_incidence, area, near_end,
      far_end, dh_du;
  std::vector<std::uint16_t> category;
  std::vector<std::uint8_t> flags;
  std::vector<std::uint8_t> unseen;      // kUnseen where u <= 0 (the same for every line)
  std::vector<std::uint8_t> none_valid;  // a row of no-data cells, beyond the scene's edge
  std::vector<float> none_z;
  SlarLineAccumulator acc;
  LineScratch(const SlarGeometry& g, int bins)
      : u(static_cast<std::size_t>(g.samples)),
        height(u.size()),
        dz_dx(u.size()),
        dz_dy(u.size()),
        range(u.size()),
        incidence(u.size()),
        local_incidence(u.size()),
        area(u.size()),
        near_end(u.size()),
        far_end(u.size()),
        dh_du(u.size()),
        category(u.size()),
        flags(u.size()),
        unseen(u.size()),
        none_valid(u.size(), 0),
        none_z(u.size(), 0.0f),
        acc(bins) {
    for (int j = 0; j < g.samples; ++j) {
      u[static_cast<std::size_t>(j)] = float(g.sample_u_m(j));
      unseen[static_cast<std::size_t>(j)] = g.sample_u_m(j) > 0.0 ? 0 : sample_flag::kUnseen;
    }
  }
};

// The cells of row r of the window (all columns) into the scratch in column
// order: height, slope (slope_difference, as surface_gradient), category and
// the no-data flag; NaN height and slope where a cell has no data. Rows
// outside the scene read `none` (no data). The interior columns take no
// branches, so the loop vectorises.
void gather_row(const SceneWindow& in, int scene_rows, int r, double dx_m, double dy_m,
                const std::uint8_t* none_valid, const float* none_z, LineScratch& s) {
  const int cols = in.cols;
  const std::size_t base = in.index(r, in.col0);
  const float* __restrict z = in.elevation_m + base;
  const std::uint8_t* __restrict v = in.valid + base;
  const std::uint16_t* __restrict cat = in.category + base;
  // North (+y) is towards row r - 1: the "hi" neighbour of dz/dy.
  const bool up_in = r - 1 >= 0, down_in = r + 1 < scene_rows;
  const float* __restrict zu = up_in ? z - in.cols : none_z;
  const std::uint8_t* __restrict vu = up_in ? v - in.cols : none_valid;
  const float* __restrict zd = down_in ? z + in.cols : none_z;
  const std::uint8_t* __restrict vd = down_in ? v + in.cols : none_valid;
  float* __restrict h = s.height.data();
  float* __restrict gx = s.dz_dx.data();
  float* __restrict gy = s.dz_dy.data();
  std::uint16_t* __restrict cg = s.category.data();
  std::uint8_t* __restrict fl = s.flags.data();
  const auto one = [&](int c, bool left_ok, bool right_ok, float zl, float zr) {
    const bool ok = v[c] != 0;
    const float zc = z[c];
    const float sx = slope_difference(left_ok, zl, right_ok, zr, zc, dx_m);
    const float sy = slope_difference(vd[c] != 0, zd[c], vu[c] != 0, zu[c], zc, dy_m);
    h[c] = ok ? zc : kNaN;
    gx[c] = ok ? sx : kNaN;
    gy[c] = ok ? sy : kNaN;
    const std::uint16_t k = cat[c];  // loaded unconditionally: no control flow
    cg[c] = ok ? k : std::uint16_t{0};
    fl[c] = ok ? std::uint8_t{0} : sample_flag::kNoData;
  };
  if (cols == 1) {
    one(0, false, false, 0.0f, 0.0f);
    return;
  }
  one(0, false, v[1] != 0, 0.0f, z[1]);
  for (int c = 1; c < cols - 1; ++c) one(c, v[c - 1] != 0, v[c + 1] != 0, z[c - 1], z[c + 1]);
  one(cols - 1, v[cols - 2] != 0, false, z[cols - 2], 0.0f);
}

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

// The constant part of a run's image formation (as form_slar_image).
detail::SlarElementContext element_context(const SlarImagingParams& p, const TwoWayGainTable& gain2,
                                           const Sigma0Lut& lut, int bins) {
  detail::SlarElementContext ctx;
  ctx.k_radar = p.transmit_power_w * p.wavelength_m * p.wavelength_m / std::pow(4.0 * kPi, 3.0);
  ctx.near_m = p.range.near_m;
  ctx.inv_dr = 1.0 / p.range.bin_m;
  ctx.bins = bins;
  ctx.gain2 = &gain2;
  ctx.lut = &lut;
  return ctx;
}

// The look geometry, element ends, cast shadow and layover of a line whose
// terrain is in the scratch (MODEL.md section 2; the code the stage path
// runs: ris/geometry/line_scan.h).
void line_geometry(const SlarGeometry& g, const LineLookFrame& frame, bool need_incidence,
                   LineScratch& s) {
  const int samples = g.samples;
  look_line({samples, s.u.data(), s.height.data(), s.dz_dx.data(), s.dz_dy.data()}, frame,
            {s.range.data(), need_incidence ? s.incidence.data() : nullptr,
             s.local_incidence.data(), s.area.data(), s.dh_du.data(), s.flags.data()});
  const LineSamples ls{samples,         g.first_sample_u_m, g.sample_step_m,   g.altitude_m,
                       s.height.data(), s.range.data(),     s.near_end.data(), s.far_end.data(),
                       s.dh_du.data(),  s.flags.data()};
  line_element_ends(ls);
  mark_shadow_and_layover(ls);
}

// Image formation's per-line step (as form_slar_image): the line's elements
// into its range profile row; counts into `counts`. Returns the number of
// elements whose centre falls in a bin.
std::int64_t accumulate_line(const detail::SlarElementContext& ctx, int samples, LineScratch& s,
                             SlarLineProfiles& prof, int line, SlarLineCounts& counts,
                             double range_window_bins) {
  constexpr std::uint8_t kSkip = sample_flag::kNoData | sample_flag::kUnseen;
  std::int64_t in_swath = 0;
  std::fill(s.acc.acc.begin(), s.acc.acc.end(), 0.0);
  std::fill(s.acc.acc_area.begin(), s.acc.acc_area.end(), 0.0);
  const std::size_t row = prof.index(line, 0);
  for (int j = 0; j < samples; ++j) {
    const std::size_t jj = static_cast<std::size_t>(j);
    const std::uint8_t sf = s.flags[jj];
    counts.nodata += (sf & sample_flag::kNoData) ? 1 : 0;
    counts.shadow += (sf & sample_flag::kShadow) ? 1 : 0;
    counts.back_facing += (sf & sample_flag::kBackFacing) ? 1 : 0;
    counts.layover += (sf & sample_flag::kLayover) ? 1 : 0;
    if (sf & kSkip) continue;
    counts.r_min_m = std::min(counts.r_min_m, s.range[jj]);
    counts.r_max_m = std::max(counts.r_max_m, s.range[jj]);
    in_swath += detail::accumulate_element(
        ctx, sf, s.range[jj], s.near_end[jj], s.far_end[jj], s.incidence[jj], s.local_incidence[jj],
        s.area[jj], s.category[jj], prof.touch.data() + row, prof.mapped_count.data() + row,
        prof.visible_count.data() + row, s.acc.acc.data(), s.acc.acc_area.data());
  }
  if (range_window_bins > 0.0) s.acc.apply_range_window(range_window_bins);
  for (int b = 0; b < prof.bins; ++b) {
    const std::size_t bb = static_cast<std::size_t>(b);
    prof.power_w[row + bb] = static_cast<float>(s.acc.acc[bb]);
    prof.area_m2[row + bb] = static_cast<float>(s.acc.acc_area[bb]);
  }
  return in_swath;
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

void SlarLineEngine::run(int line0, int line1, const SceneWindow& in, SlarLineProfiles& prof,
                         const SceneMapsWindow& maps, SlarLineCounts& counts) const {
  const SlarGeometry& g = g_;
  const Scene& scene = scene_;
  const Track& t = g.track;
  const double H = g.altitude_m;
  const int samples = g.samples;
  const int bins = prof.bins;
  const LineLookFrame frame{H, t.cross_x, t.cross_y, g.line_spacing_m * g.sample_step_m};
  const bool need_incidence = !gain2_.uniform();
  const double near_m = params_.range.near_m, far_m = params_.range.far_m();

  const detail::SlarElementContext ctx = element_context(params_, gain2_, lut_, bins);

  const auto ok = [&](int r, int c) {
    return scene.contains(r, c) && in.valid[in.index(r, c)] != 0;
  };
  const auto z = [&](int r, int c) {
    return scene.contains(r, c) ? in.elevation_m[in.index(r, c)] : 0.0f;
  };

  std::int64_t in_swath = 0;
#pragma omp parallel reduction(+ : in_swath)
  {
    LineScratch s(g, bins);
    SlarLineCounts local;
#pragma omp for schedule(dynamic, 16)
    for (int line = line0; line < line1; ++line) {
      const int lc = line_cell(scene, g, cross_is_x_, line);
      const auto cell_of = [&](int j, int& r, int& c) {
        if (cross_is_x_) {
          r = lc;
          c = u_grows_with_index_ ? j : scene.cols - 1 - j;
        } else {
          c = lc;
          r = u_grows_with_index_ ? j : scene.rows - 1 - j;
        }
      };

      // The terrain under each sample (as slar_geometry.cpp fill_line with
      // its DirectSampler, the slope computed in place as surface_gradient).
      if (cross_is_x_ && lc >= 0 && in.col0 == 0 && in.cols == samples) {
        // A row of cells, contiguous in memory.
        gather_row(in, scene.rows, lc, scene.dx_m, scene.dy_m, s.none_valid.data(), s.none_z.data(),
                   s);
        if (!u_grows_with_index_) {
          std::reverse(s.height.begin(), s.height.end());
          std::reverse(s.dz_dx.begin(), s.dz_dx.end());
          std::reverse(s.dz_dy.begin(), s.dz_dy.end());
          std::reverse(s.category.begin(), s.category.end());
          std::reverse(s.flags.begin(), s.flags.end());
        }
        for (int j = 0; j < samples; ++j)
          s.flags[static_cast<std::size_t>(j)] |= s.unseen[static_cast<std::size_t>(j)];
      } else
        for (int j = 0; j < samples; ++j) {
          const std::size_t jj = static_cast<std::size_t>(j);
          std::uint8_t f = 0;
          int r = 0, c = 0;
          bool valid = false;
          if (lc < 0) {
            f |= sample_flag::kUnseen;
          } else {
            cell_of(j, r, c);
            valid = in.valid[in.index(r, c)] != 0;
            if (!valid) f |= sample_flag::kNoData;
          }
          if (!(g.sample_u_m(j) > 0.0)) f |= sample_flag::kUnseen;
          s.flags[jj] = f;
          if (lc < 0 || !valid) {
            s.height[jj] = s.dz_dx[jj] = s.dz_dy[jj] = kNaN;
            s.category[jj] = 0;
            continue;
          }
          const std::size_t i = in.index(r, c);
          const float zc = in.elevation_m[i];
          s.height[jj] = zc;
          s.dz_dx[jj] = slope_difference(ok(r, c - 1), z(r, c - 1), ok(r, c + 1), z(r, c + 1), zc,
                                         scene.dx_m);
          // North (+y) is towards row r - 1.
          s.dz_dy[jj] = slope_difference(ok(r + 1, c), z(r + 1, c), ok(r - 1, c), z(r - 1, c), zc,
                                         scene.dy_m);
          s.category[jj] = in.category[i];
        }

      line_geometry(g, frame, need_incidence, s);
      in_swath += accumulate_line(ctx, samples, s, prof, line, local, params_.range_window_bins);

      // The scene-grid maps (scene_geometry_maps: each cell is its own
      // sample here).
      if (lc >= 0) {
        for (int j = 0; j < samples; ++j) {
          const std::size_t jj = static_cast<std::size_t>(j);
          int r = 0, c = 0;
          cell_of(j, r, c);
          const std::size_t cell = maps.index(r, c);
          scene_map_cell(in.valid[in.index(r, c)] != 0, s.flags[jj], s.range[jj],
                         s.local_incidence[jj], near_m, far_m, maps.mask[cell],
                         maps.local_incidence_deg[cell]);
        }
      }
    }
#pragma omp critical(ris_slar_line_counts)
    counts.add(local);
  }
  prof.samples_in_swath += in_swath;
}

bool fused_slar_image_applies(const Scene& scene, const SlarGeometry& layout) {
  return fused_slar_applies(scene, layout) || !layout.direct_sampling;
}

namespace {

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

// The fused run for any other heading: the stage path's bilinear sampler
// (slar_geometry.cpp fill_line with BilinearSampler: bilinear height and
// slope at half a cell, the nearest cell's category) line by line, then the
// shared line geometry and image formation, and the scene maps scattered
// per line. Only the slope rasters (8 bytes per cell) are whole-scene.
void run_oblique(const Scene& scene, const SlarGeometry& g, const Sigma0Lut& lut,
                 const SlarImagingParams& p, const std::string& radar_file, SlarLineProfiles& prof,
                 SceneGeometryMaps& maps, SlarLineCounts& counts) {
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

}  // namespace

SlarImage form_slar_image_fused(const Scene& scene, SlarGeometry& g, SceneGeometryMaps& maps,
                                const Sigma0Lut& lut, const SlarImagingParams& p,
                                const std::string& radar_file) {
  RIS_CHECK(fused_slar_image_applies(scene, g));
  RIS_CHECK(p.range.count > 0 && p.range.bin_m > 0.0);
  RIS_CHECK(p.azimuth_beamwidth_rad > 0.0);
  SlarLineProfiles prof;
  prof.allocate(g.lines, p.range.count);
  maps.mask.assign(scene.size(), 0);
  maps.local_incidence_deg.resize(scene.size());
  SlarLineCounts counts;
  if (g.direct_sampling) {
    const SlarLineEngine engine(scene, g, lut, p, radar_file);
    const SceneMapsWindow out{
        0, 0, scene.rows, scene.cols, maps.mask.data(), maps.local_incidence_deg.data()};
    engine.run(0, g.lines, SceneWindow::whole(scene), prof, out, counts);
  } else {
    run_oblique(scene, g, lut, p, radar_file, prof, maps, counts);
  }
  g.nodata_samples = counts.nodata;
  g.shadow_samples = counts.shadow;
  g.back_facing_samples = counts.back_facing;
  g.layover_samples = counts.layover;
  g.nodata_cells = static_cast<std::int64_t>(std::count(scene.valid.begin(), scene.valid.end(), 0));
  if (prof.samples_in_swath == 0) {
    throw InputError(radar_file, "sweep_delay",
                     fmt::format("the swath (slant range {:.1f} to {:.1f} m) misses the scene, "
                                 "which spans slant range {:.1f} to {:.1f} m; expected a sweep "
                                 "delay and length (or near range and range bins) that overlap it",
                                 p.range.near_m, p.range.far_m(), counts.r_min_m, counts.r_max_m));
  }
  SlarImage img;
  img.lines = g.lines;
  img.bins = p.range.count;
  img.range = p.range;
  img.line_spacing_m = g.line_spacing_m;
  img.samples_in_swath = prof.samples_in_swath;
  integrate_slar_azimuth(prof, p, g.line_spacing_m, img);
  img.mapped_count = std::move(prof.mapped_count);
  img.visible_count = std::move(prof.visible_count);
  return img;
}

}  // namespace ris
