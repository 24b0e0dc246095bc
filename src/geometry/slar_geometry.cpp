#include "ris/geometry/slar_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ris/geometry/surface_gradient.h"
#include "ris/util/error.h"

namespace ris {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// What a sampler returns for one ground point.
struct TerrainSample {
  bool inside = false;  // within the scene
  bool valid = false;   // has data
  float height_m = 0.0f;
  float dz_dx = 0.0f;
  float dz_dy = 0.0f;
  std::uint16_t category = 0;
};

// Track along a grid axis: samples are cells. The line picks the nearest row
// (or column) of cells, sample j the j-th cell in increasing u.
struct DirectSampler {
  const Scene* scene = nullptr;
  const SurfaceGradient* grad = nullptr;
  bool cross_is_x = true;  // look direction along +-x (track along y)
  bool u_grows_with_index = true;
  int line_cell = -1;  // row (cross_is_x) or column of the current line; -1: outside

  void start_line(const Track& t, double s_m) {
    const auto [x, y] = t.world_from_along_cross(s_m, 0.0);
    const auto [cf, rf] = scene->grid_from_world(x, y);
    const double f = cross_is_x ? rf : cf;
    const int n = cross_is_x ? scene->rows : scene->cols;
    line_cell = (f >= 0.0 && f < n) ? static_cast<int>(std::floor(f)) : -1;
  }

  TerrainSample at(int j) const {
    TerrainSample ts;
    if (line_cell < 0) return ts;
    int r = 0, c = 0;
    if (cross_is_x) {
      r = line_cell;
      c = u_grows_with_index ? j : scene->cols - 1 - j;
    } else {
      c = line_cell;
      r = u_grows_with_index ? j : scene->rows - 1 - j;
    }
    const std::size_t i = scene->index(r, c);
    ts.inside = true;
    ts.valid = scene->valid[i] != 0;
    if (!ts.valid) return ts;
    ts.height_m = scene->elevation_m[i];
    ts.dz_dx = grad->dz_dx[i];
    ts.dz_dy = grad->dz_dy[i];
    ts.category = scene->category[i];
    return ts;
  }
};

// Any heading: bilinear elevation and slope, nearest category.
struct BilinearSampler {
  const Scene* scene = nullptr;
  const SurfaceGradient* grad = nullptr;
  const Track* track = nullptr;
  double first_u_m = 0.0;
  double step_m = 0.0;
  double line_x = 0.0, line_y = 0.0;  // world point of (s, u = 0)

  void start_line(const Track& t, double s_m) {
    const auto [x, y] = t.world_from_along_cross(s_m, 0.0);
    line_x = x;
    line_y = y;
  }

  TerrainSample at(int j) const {
    TerrainSample ts;
    const double u = first_u_m + j * step_m;
    const double x = line_x + u * track->cross_x;
    const double y = line_y + u * track->cross_y;
    const auto [cf, rf] = scene->grid_from_world(x, y);
    const int cols = scene->cols, rows = scene->rows;
    if (!(cf >= 0.0 && cf <= cols && rf >= 0.0 && rf <= rows)) return ts;
    ts.inside = true;
    // Cell centres sit at integer + 0.5; clamp to the outermost centres.
    const double px = std::clamp(cf - 0.5, 0.0, double(cols - 1));
    const double py = std::clamp(rf - 0.5, 0.0, double(rows - 1));
    const int c0 = std::min(static_cast<int>(px), std::max(cols - 2, 0));
    const int r0 = std::min(static_cast<int>(py), std::max(rows - 2, 0));
    const int c1 = std::min(c0 + 1, cols - 1), r1 = std::min(r0 + 1, rows - 1);
    const double fx = px - c0, fy = py - r0;
    const double w[4] = {(1 - fx) * (1 - fy), fx * (1 - fy), (1 - fx) * fy, fx * fy};
    const std::size_t idx[4] = {scene->index(r0, c0), scene->index(r0, c1), scene->index(r1, c0),
                                scene->index(r1, c1)};
    double h = 0.0, gx = 0.0, gy = 0.0;
    for (int k = 0; k < 4; ++k) {
      if (w[k] <= 0.0) continue;
      if (!scene->valid[idx[k]]) return ts;  // touches no data
      h += w[k] * scene->elevation_m[idx[k]];
      gx += w[k] * grad->dz_dx[idx[k]];
      gy += w[k] * grad->dz_dy[idx[k]];
    }
    const int cn = std::min(static_cast<int>(cf), cols - 1);
    const int rn = std::min(static_cast<int>(rf), rows - 1);
    ts.valid = true;
    ts.height_m = static_cast<float>(h);
    ts.dz_dx = static_cast<float>(gx);
    ts.dz_dy = static_cast<float>(gy);
    ts.category = scene->category[scene->index(rn, cn)];
    return ts;
  }
};

bool nearly(double a, double b) {
  return std::abs(a - b) < 1e-9;
}

// Fills one line: per-sample quantities, then the shadow and layover scans.
template <typename Sampler>
void fill_line(SlarGeometry& g, Sampler& sampler, int line, std::vector<float>& dh_du_scratch) {
  const Track& t = g.track;
  const double H = g.altitude_m;
  sampler.start_line(t, g.line_s_m(line));
  const std::size_t base = g.index(line, 0);
  const double element_m2 = g.line_spacing_m * g.sample_step_m;

  for (int j = 0; j < g.samples; ++j) {
    const std::size_t i = base + static_cast<std::size_t>(j);
    const double u = g.sample_u_m(j);
    const TerrainSample ts = sampler.at(j);
    std::uint8_t f = 0;
    if (!ts.inside) f |= sample_flag::kUnseen;
    if (ts.inside && !ts.valid) f |= sample_flag::kNoData;
    if (!(u > 0.0)) f |= sample_flag::kUnseen;
    if (!ts.inside || !ts.valid) {
      g.height_m[i] = g.slant_range_m[i] = g.incidence_rad[i] = kNaN;
      g.local_incidence_rad[i] = g.area_m2[i] = kNaN;
      g.range_near_end_m[i] = g.range_far_end_m[i] = kNaN;
      g.category[i] = 0;
      g.flags[i] = f;
      continue;
    }
    const double h = ts.height_m;
    const double D = H - h;  // > 0: checked before
    const double R = std::hypot(u, D);
    // Slope along the look direction g and the facet normal's length
    // |(-dz/dx, -dz/dy, 1)| (MODEL.md section 2-3).
    const double dh_du = double(ts.dz_dx) * t.cross_x + double(ts.dz_dy) * t.cross_y;
    const double n_len = std::sqrt(1.0 + double(ts.dz_dx) * ts.dz_dx + double(ts.dz_dy) * ts.dz_dy);
    // cos(theta_l) = n . l with l = (-u g + D z) / R: the along-track slope
    // tilts n but is orthogonal to l, so only dh/du enters the numerator.
    const double cos_l = (u * dh_du + D) / (R * n_len);
    if (cos_l <= 0.0) f |= sample_flag::kBackFacing;
    g.height_m[i] = ts.height_m;
    g.slant_range_m[i] = static_cast<float>(R);
    g.incidence_rad[i] = static_cast<float>(std::atan2(u, D));
    g.local_incidence_rad[i] = static_cast<float>(std::acos(std::clamp(cos_l, -1.0, 1.0)));
    g.area_m2[i] = static_cast<float>(element_m2 * n_len);
    dh_du_scratch[static_cast<std::size_t>(j)] = static_cast<float>(dh_du);
    g.category[i] = ts.category;
    g.flags[i] = f;
  }

  // The element's ends: heights halfway to the neighbours with data.
  constexpr std::uint8_t kSkip = sample_flag::kNoData | sample_flag::kUnseen;
  const double half_step = 0.5 * g.sample_step_m;
  const auto has_data = [&](int j) {
    return j >= 0 && j < g.samples && !(g.flags[base + static_cast<std::size_t>(j)] & kSkip);
  };
  for (int j = 0; j < g.samples; ++j) {
    const std::size_t i = base + static_cast<std::size_t>(j);
    if (!has_data(j)) continue;
    const double h = g.height_m[i];
    const double slope_half = dh_du_scratch[static_cast<std::size_t>(j)] * half_step;
    const double h_near = has_data(j - 1) ? 0.5 * (h + g.height_m[i - 1]) : h - slope_half;
    const double h_far = has_data(j + 1) ? 0.5 * (h + g.height_m[i + 1]) : h + slope_half;
    const double u = g.sample_u_m(j);
    g.range_near_end_m[i] = static_cast<float>(std::hypot(u - half_step, H - h_near));
    g.range_far_end_m[i] = static_cast<float>(std::hypot(u + half_step, H - h_far));
  }

  // Cast shadow: t(u) = u / (H - h); a point is shadowed when a nearer point
  // has a larger t (MODEL.md section 2).
  double max_t = -std::numeric_limits<double>::infinity();
  for (int j = 0; j < g.samples; ++j) {
    const std::size_t i = base + static_cast<std::size_t>(j);
    if (g.flags[i] & kSkip) continue;
    const double tt = g.sample_u_m(j) / (H - double(g.height_m[i]));
    if (max_t > tt) g.flags[i] |= sample_flag::kShadow;
    max_t = std::max(max_t, tt);
  }
  // Layover, SNAP definition: near to far keeping the largest R, a smaller R
  // is layover; far to near keeping the smallest R, a larger R is layover.
  float max_r = -std::numeric_limits<float>::infinity();
  for (int j = 0; j < g.samples; ++j) {
    const std::size_t i = base + static_cast<std::size_t>(j);
    if (g.flags[i] & kSkip) continue;
    if (g.slant_range_m[i] < max_r) g.flags[i] |= sample_flag::kLayover;
    max_r = std::max(max_r, g.slant_range_m[i]);
  }
  float min_r = std::numeric_limits<float>::infinity();
  for (int j = g.samples - 1; j >= 0; --j) {
    const std::size_t i = base + static_cast<std::size_t>(j);
    if (g.flags[i] & kSkip) continue;
    if (g.slant_range_m[i] > min_r) g.flags[i] |= sample_flag::kLayover;
    min_r = std::min(min_r, g.slant_range_m[i]);
  }
}

}  // namespace

void check_terrain_below_sensor(const Scene& scene, double altitude_m, const std::string& file) {
  std::size_t worst = scene.size();
  float max_h = -std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (scene.valid[i] && scene.elevation_m[i] > max_h) {
      max_h = scene.elevation_m[i];
      worst = i;
    }
  }
  if (worst < scene.size() && double(max_h) >= altitude_m) {
    const int r = static_cast<int>(worst / static_cast<std::size_t>(scene.cols));
    const int c = static_cast<int>(worst % static_cast<std::size_t>(scene.cols));
    throw InputError(file, "altitude",
                     fmt::format("the terrain reaches {:.1f} m (scene row {}, column {}), at or "
                                 "above the sensor altitude {:.1f} m; expected an altitude above "
                                 "the highest terrain",
                                 max_h, r, c, altitude_m));
  }
}

SlarGeometry slar_geometry_layout(const Scene& scene, const Track& track, double line_spacing_m) {
  SlarGeometry g;
  g.track = track;
  g.altitude_m = track.altitude_m;
  const bool along_y = nearly(std::abs(track.along_y), 1.0);
  const bool along_x = nearly(std::abs(track.along_x), 1.0);
  g.direct_sampling = along_x || along_y;
  const double along_cell_m =
      along_y ? scene.dy_m : (along_x ? scene.dx_m : std::min(scene.dx_m, scene.dy_m));
  g.line_spacing_m = line_spacing_m > 0.0 ? line_spacing_m : along_cell_m;
  g.lines = std::max(1, static_cast<int>(std::floor(track.length_m / g.line_spacing_m + 1e-6)));

  // The scene's extent in u, from its corners.
  double u_min = std::numeric_limits<double>::infinity(), u_max = -u_min;
  for (int r : {0, scene.rows}) {
    for (int c : {0, scene.cols}) {
      const auto [x, y] = scene.world_from_grid(c, r);
      const double u = track.along_cross(x, y).second;
      u_min = std::min(u_min, u);
      u_max = std::max(u_max, u);
    }
  }
  if (g.direct_sampling) {
    g.sample_step_m = along_y ? scene.dx_m : scene.dy_m;
    g.samples = along_y ? scene.cols : scene.rows;
    g.first_sample_u_m = u_min + 0.5 * g.sample_step_m;  // nearest cell centre
  } else {
    g.sample_step_m = 0.5 * std::min(scene.dx_m, scene.dy_m);
    const double u0 = std::max(u_min, 0.0) + 0.5 * g.sample_step_m;
    g.first_sample_u_m = u0;
    g.samples = u_max > u0 ? static_cast<int>(std::floor((u_max - u0) / g.sample_step_m)) + 1 : 1;
  }
  return g;
}

SlarGeometry compute_slar_geometry(const Scene& scene, const Track& track, double line_spacing_m,
                                   const std::string& radar_file) {
  scene.validate("scene");
  check_terrain_below_sensor(scene, track.altitude_m, radar_file);
  SlarGeometry g = slar_geometry_layout(scene, track, line_spacing_m);
  const bool along_y = nearly(std::abs(track.along_y), 1.0);

  const SurfaceGradient grad = surface_gradient(scene);
  DirectSampler direct;
  BilinearSampler bilinear;
  if (g.direct_sampling) {
    direct.scene = &scene;
    direct.grad = &grad;
    direct.cross_is_x = along_y;
    direct.u_grows_with_index = along_y ? track.cross_x > 0.0 : track.cross_y < 0.0;
  } else {
    bilinear.scene = &scene;
    bilinear.grad = &grad;
    bilinear.track = &g.track;
    bilinear.first_u_m = g.first_sample_u_m;
    bilinear.step_m = g.sample_step_m;
  }

  const std::size_t n = static_cast<std::size_t>(g.lines) * static_cast<std::size_t>(g.samples);
  g.height_m.resize(n);
  g.slant_range_m.resize(n);
  g.incidence_rad.resize(n);
  g.local_incidence_rad.resize(n);
  g.area_m2.resize(n);
  g.range_near_end_m.resize(n);
  g.range_far_end_m.resize(n);
  g.category.resize(n);
  g.flags.resize(n);

  // Lines are independent: one line per iteration, samplers copied per
  // thread (they hold only the current line's position), scratch per thread.
#pragma omp parallel firstprivate(direct, bilinear)
  {
    std::vector<float> dh_du(static_cast<std::size_t>(g.samples));
#pragma omp for schedule(dynamic, 16)
    for (int line = 0; line < g.lines; ++line) {
      if (g.direct_sampling)
        fill_line(g, direct, line, dh_du);
      else
        fill_line(g, bilinear, line, dh_du);
    }
  }

  std::int64_t nodata = 0, shadow = 0, back = 0, layover = 0;
#pragma omp parallel for reduction(+ : nodata, shadow, back, layover) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t f = g.flags[i];
    nodata += (f & sample_flag::kNoData) ? 1 : 0;
    shadow += (f & sample_flag::kShadow) ? 1 : 0;
    back += (f & sample_flag::kBackFacing) ? 1 : 0;
    layover += (f & sample_flag::kLayover) ? 1 : 0;
  }
  g.nodata_samples = nodata;
  g.shadow_samples = shadow;
  g.back_facing_samples = back;
  g.layover_samples = layover;
  g.nodata_cells = static_cast<std::int64_t>(std::count(scene.valid.begin(), scene.valid.end(), 0));
  return g;
}

}  // namespace ris
