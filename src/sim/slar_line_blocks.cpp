#include "ris/sim/slar_line_blocks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "image/slar_element.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Slope from the two neighbours (lo at -step, hi at +step) of a valid centre:
// the same expression as ris/geometry/surface_gradient.cpp, so the slopes are
// the same floats.
inline float difference(bool lo_ok, float z_lo, bool hi_ok, float z_hi, float z_c, double step_m) {
  if (lo_ok && hi_ok) return static_cast<float>((double(z_hi) - double(z_lo)) / (2.0 * step_m));
  if (hi_ok) return static_cast<float>((double(z_hi) - double(z_c)) / step_m);
  if (lo_ok) return static_cast<float>((double(z_c) - double(z_lo)) / step_m);
  return 0.0f;
}

bool nearly(double a, double b) {
  return std::abs(a - b) < 1e-9;
}

// One thread's line scratch, allocated once per run() call and thread.
struct LineScratch {
  std::vector<float> height, range, incidence, local_incidence, area, near_end, far_end, dh_du;
  std::vector<std::uint16_t> category;
  std::vector<std::uint8_t> flags;
  SlarLineAccumulator acc;
  LineScratch(int samples, int bins)
      : height(static_cast<std::size_t>(samples)),
        range(static_cast<std::size_t>(samples)),
        incidence(static_cast<std::size_t>(samples)),
        local_incidence(static_cast<std::size_t>(samples)),
        area(static_cast<std::size_t>(samples)),
        near_end(static_cast<std::size_t>(samples)),
        far_end(static_cast<std::size_t>(samples)),
        dh_du(static_cast<std::size_t>(samples)),
        category(static_cast<std::size_t>(samples)),
        flags(static_cast<std::size_t>(samples)),
        acc(bins) {}
};

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
  const double element_m2 = g.line_spacing_m * g.sample_step_m;
  const double half_step = 0.5 * g.sample_step_m;
  const bool need_incidence = !gain2_.uniform();
  const double near_m = params_.range.near_m, far_m = params_.range.far_m();

  detail::SlarElementContext ctx;
  ctx.k_radar = params_.transmit_power_w * params_.wavelength_m * params_.wavelength_m /
                std::pow(4.0 * kPi, 3.0);
  ctx.near_m = near_m;
  ctx.inv_dr = 1.0 / params_.range.bin_m;
  ctx.bins = bins;
  ctx.gain2 = &gain2_;
  ctx.lut = &lut_;

  const auto ok = [&](int r, int c) {
    return scene.contains(r, c) && in.valid[in.index(r, c)] != 0;
  };
  const auto z = [&](int r, int c) {
    return scene.contains(r, c) ? in.elevation_m[in.index(r, c)] : 0.0f;
  };

  std::int64_t in_swath = 0;
#pragma omp parallel reduction(+ : in_swath)
  {
    LineScratch s(samples, bins);
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

      // Per-sample quantities (as slar_geometry.cpp fill_line with its
      // DirectSampler, the slope computed in place).
      for (int j = 0; j < samples; ++j) {
        const std::size_t jj = static_cast<std::size_t>(j);
        const double u = g.sample_u_m(j);
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
        if (!(u > 0.0)) f |= sample_flag::kUnseen;
        if (lc < 0 || !valid) {
          s.height[jj] = s.range[jj] = s.incidence[jj] = kNaN;
          s.local_incidence[jj] = s.area[jj] = kNaN;
          s.near_end[jj] = s.far_end[jj] = kNaN;
          s.category[jj] = 0;
          s.flags[jj] = f;
          continue;
        }
        const std::size_t i = in.index(r, c);
        const float zc = in.elevation_m[i];
        const float dz_dx =
            difference(ok(r, c - 1), z(r, c - 1), ok(r, c + 1), z(r, c + 1), zc, scene.dx_m);
        // North (+y) is towards row r - 1.
        const float dz_dy =
            difference(ok(r + 1, c), z(r + 1, c), ok(r - 1, c), z(r - 1, c), zc, scene.dy_m);
        const double h = zc;
        const double D = H - h;
        const double R = std::hypot(u, D);
        const double dh_du = double(dz_dx) * t.cross_x + double(dz_dy) * t.cross_y;
        const double n_len = std::sqrt(1.0 + double(dz_dx) * dz_dx + double(dz_dy) * dz_dy);
        const double cos_l = (u * dh_du + D) / (R * n_len);
        if (cos_l <= 0.0) f |= sample_flag::kBackFacing;
        s.height[jj] = zc;
        s.range[jj] = static_cast<float>(R);
        s.incidence[jj] = need_incidence ? static_cast<float>(std::atan2(u, D)) : 0.0f;
        s.local_incidence[jj] = static_cast<float>(std::acos(std::clamp(cos_l, -1.0, 1.0)));
        s.area[jj] = static_cast<float>(element_m2 * n_len);
        s.dh_du[jj] = static_cast<float>(dh_du);
        s.category[jj] = in.category[i];
        s.flags[jj] = f;
      }

      // The element's ends: heights halfway to the neighbours with data.
      constexpr std::uint8_t kSkip = sample_flag::kNoData | sample_flag::kUnseen;
      const auto has_data = [&](int j) {
        return j >= 0 && j < samples && !(s.flags[static_cast<std::size_t>(j)] & kSkip);
      };
      for (int j = 0; j < samples; ++j) {
        const std::size_t jj = static_cast<std::size_t>(j);
        if (!has_data(j)) continue;
        const double h = s.height[jj];
        const double slope_half = s.dh_du[jj] * half_step;
        const double h_near = has_data(j - 1) ? 0.5 * (h + s.height[jj - 1]) : h - slope_half;
        const double h_far = has_data(j + 1) ? 0.5 * (h + s.height[jj + 1]) : h + slope_half;
        const double u = g.sample_u_m(j);
        s.near_end[jj] = static_cast<float>(std::hypot(u - half_step, H - h_near));
        s.far_end[jj] = static_cast<float>(std::hypot(u + half_step, H - h_far));
      }

      // Cast shadow and layover (MODEL.md section 2; as fill_line).
      double max_t = -std::numeric_limits<double>::infinity();
      for (int j = 0; j < samples; ++j) {
        const std::size_t jj = static_cast<std::size_t>(j);
        if (s.flags[jj] & kSkip) continue;
        const double tt = g.sample_u_m(j) / (H - double(s.height[jj]));
        if (max_t > tt) s.flags[jj] |= sample_flag::kShadow;
        max_t = std::max(max_t, tt);
      }
      float max_r = -std::numeric_limits<float>::infinity();
      for (int j = 0; j < samples; ++j) {
        const std::size_t jj = static_cast<std::size_t>(j);
        if (s.flags[jj] & kSkip) continue;
        if (s.range[jj] < max_r) s.flags[jj] |= sample_flag::kLayover;
        max_r = std::max(max_r, s.range[jj]);
      }
      float min_r = std::numeric_limits<float>::infinity();
      for (int j = samples - 1; j >= 0; --j) {
        const std::size_t jj = static_cast<std::size_t>(j);
        if (s.flags[jj] & kSkip) continue;
        if (s.range[jj] > min_r) s.flags[jj] |= sample_flag::kLayover;
        min_r = std::min(min_r, s.range[jj]);
      }

      // Image formation (form_slar_image's per-line step) and the scene-grid
      // maps (scene_geometry_maps: each cell is its own sample here).
      std::fill(s.acc.acc.begin(), s.acc.acc.end(), 0.0);
      std::fill(s.acc.acc_area.begin(), s.acc.acc_area.end(), 0.0);
      const std::size_t row = prof.index(line, 0);
      for (int j = 0; j < samples; ++j) {
        const std::size_t jj = static_cast<std::size_t>(j);
        const std::uint8_t sf = s.flags[jj];
        local.nodata += (sf & sample_flag::kNoData) ? 1 : 0;
        local.shadow += (sf & sample_flag::kShadow) ? 1 : 0;
        local.back_facing += (sf & sample_flag::kBackFacing) ? 1 : 0;
        local.layover += (sf & sample_flag::kLayover) ? 1 : 0;
        const bool has = !(sf & kSkip);
        if (has) {
          local.r_min_m = std::min(local.r_min_m, s.range[jj]);
          local.r_max_m = std::max(local.r_max_m, s.range[jj]);
          in_swath += detail::accumulate_element(
              ctx, sf, s.range[jj], s.near_end[jj], s.far_end[jj], s.incidence[jj],
              s.local_incidence[jj], s.area[jj], s.category[jj], prof.touch.data() + row,
              prof.mapped_count.data() + row, prof.visible_count.data() + row, s.acc.acc.data(),
              s.acc.acc_area.data());
        }
        if (lc < 0) continue;
        int r = 0, c = 0;
        cell_of(j, r, c);
        std::uint8_t m = in.valid[in.index(r, c)] ? 0 : scene_flag::kNoData;
        if (sf & sample_flag::kNoData) m |= scene_flag::kNoData;
        if (sf & sample_flag::kShadow) m |= scene_flag::kShadow;
        if (sf & sample_flag::kLayover) m |= scene_flag::kLayover;
        if (sf & sample_flag::kBackFacing) m |= scene_flag::kBackFacing;
        const double R = s.range[jj];
        if ((sf & sample_flag::kUnseen) || (has && !(R >= near_m && R < far_m))) {
          m |= scene_flag::kOutsideSwath;
        }
        const std::size_t cell = maps.index(r, c);
        maps.local_incidence_deg[cell] = (has && !(m & scene_flag::kNoData))
                                             ? static_cast<float>(rad_to_deg(s.local_incidence[jj]))
                                             : kNaN;
        maps.mask[cell] = m;
      }
      for (int b = 0; b < bins; ++b) {
        const std::size_t bb = static_cast<std::size_t>(b);
        prof.power_w[row + bb] = static_cast<float>(s.acc.acc[bb]);
        prof.area_m2[row + bb] = static_cast<float>(s.acc.acc_area[bb]);
      }
    }
#pragma omp critical(ris_slar_line_counts)
    counts.add(local);
  }
  prof.samples_in_swath += in_swath;
}

SlarImage form_slar_image_fused(const Scene& scene, SlarGeometry& g, SceneGeometryMaps& maps,
                                const Sigma0Lut& lut, const SlarImagingParams& p,
                                const std::string& radar_file) {
  RIS_CHECK(fused_slar_applies(scene, g));
  RIS_CHECK(p.range.count > 0 && p.range.bin_m > 0.0);
  RIS_CHECK(p.azimuth_beamwidth_rad > 0.0);
  const SlarLineEngine engine(scene, g, lut, p, radar_file);
  SlarLineProfiles prof;
  prof.allocate(g.lines, p.range.count);
  maps.mask.assign(scene.size(), 0);
  maps.local_incidence_deg.resize(scene.size());
  const SceneMapsWindow out{
      0, 0, scene.rows, scene.cols, maps.mask.data(), maps.local_incidence_deg.data()};
  SlarLineCounts counts;
  engine.run(0, g.lines, SceneWindow::whole(scene), prof, out, counts);
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
