#include "ris/geometry/slar_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "kernels/geometry/terrain_height_kernels.h"
#include "ris/geometry/line_scan.h"
#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_line.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"

namespace ris {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

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

bool nearly(double a, double b) {
  return std::abs(a - b) < 1e-9;
}

// One thread's line scratch (allocated once per thread).
struct LineScratch {
  std::vector<float> u, dz_dx, dz_dy, dh_du;
  explicit LineScratch(const SlarGeometry& g)
      : u(static_cast<std::size_t>(g.samples)), dz_dx(u.size()), dz_dy(u.size()), dh_du(u.size()) {
    for (int j = 0; j < g.samples; ++j) u[static_cast<std::size_t>(j)] = float(g.sample_u_m(j));
  }
};

// The look geometry over samples [j0, j0 + n) of a line whose terrain is in
// place (look_line), then the element ends and the shadow and layover scans
// (shared with PPI rays and the fused path: ris/geometry/line_scan.h). The
// scans skip unseen samples, so running them on the seen span alone gives
// the same flags.
void scan_line(SlarGeometry& g, int line, int j0, int n, LineScratch& s) {
  const Track& t = g.track;
  const double H = g.altitude_m;
  const std::size_t base = g.index(line, 0) + static_cast<std::size_t>(j0);
  const std::size_t o = static_cast<std::size_t>(j0);
  const LineTerrain terrain{n, s.u.data() + o, &g.height_m[base], s.dz_dx.data() + o,
                            s.dz_dy.data() + o};
  const LineLookFrame frame{H, t.cross_x, t.cross_y, g.line_spacing_m * g.sample_step_m};
  look_line(terrain, frame,
            {&g.slant_range_m[base], &g.incidence_rad[base], &g.local_incidence_rad[base],
             &g.area_m2[base], s.dh_du.data() + o, &g.flags[base]});
  const LineSamples ls{n,
                       g.sample_u_m(j0),
                       g.sample_step_m,
                       H,
                       &g.height_m[base],
                       &g.slant_range_m[base],
                       &g.range_near_end_m[base],
                       &g.range_far_end_m[base],
                       s.dh_du.data() + o,
                       &g.flags[base]};
  line_element_ends(ls);
  mark_shadow_and_layover(ls);
}

// Fills one line along a grid axis: the terrain under each sample, then the
// line's scans.
void fill_direct_line(SlarGeometry& g, DirectSampler& sampler, int line, LineScratch& s) {
  sampler.start_line(g.track, g.line_s_m(line));
  const std::size_t base = g.index(line, 0);
  for (int j = 0; j < g.samples; ++j) {
    const std::size_t i = base + static_cast<std::size_t>(j);
    const std::size_t jj = static_cast<std::size_t>(j);
    const TerrainSample ts = sampler.at(j);
    std::uint8_t f = 0;
    if (!ts.inside) f |= sample_flag::kUnseen;
    if (ts.inside && !ts.valid) f |= sample_flag::kNoData;
    if (!(g.sample_u_m(j) > 0.0)) f |= sample_flag::kUnseen;
    g.flags[i] = f;
    const bool terrain = ts.inside && ts.valid;
    g.height_m[i] = terrain ? ts.height_m : kNaN;
    s.dz_dx[jj] = terrain ? ts.dz_dx : kNaN;
    s.dz_dy[jj] = terrain ? ts.dz_dy : kNaN;
    g.category[i] = terrain ? ts.category : 0;
  }
  scan_line(g, line, 0, g.samples, s);
}

// Fills one line off the grid axes: the samples within the scene from the
// line sampler, then the scans over them; the others unseen (NaN, as the
// scans would leave a sample without terrain).
void fill_oblique_line(const Scene& scene, const TerrainTexels& tex, SlarGeometry& g, int line,
                       LineScratch& s) {
  const SlarLineSpan span = slar_line_span(scene, g, line);
  const std::size_t base = g.index(line, 0);
  const auto unseen = [&](int j0, int j1) {
    for (int j = j0; j < j1; ++j) {
      const std::size_t i = base + static_cast<std::size_t>(j);
      g.height_m[i] = g.slant_range_m[i] = g.incidence_rad[i] = g.local_incidence_rad[i] = kNaN;
      g.area_m2[i] = g.range_near_end_m[i] = g.range_far_end_m[i] = kNaN;
      g.category[i] = 0;
      g.flags[i] = sample_flag::kUnseen;
    }
  };
  unseen(0, span.begin);
  unseen(span.end, g.samples);
  const std::size_t b = base + static_cast<std::size_t>(span.begin);
  const std::size_t o = static_cast<std::size_t>(span.begin);
  sample_terrain_line(
      tex, span.grid, span.begin, span.end,
      {&g.height_m[b], s.dz_dx.data() + o, s.dz_dy.data() + o, &g.category[b], &g.flags[b]});
  scan_line(g, line, span.begin, span.end - span.begin, s);
}

}  // namespace

void check_terrain_below_sensor(const Scene& scene, double altitude_m, const std::string& file) {
  // Almost always nothing reaches the sensor: first a branch-free scan that
  // only says whether a cell does, then, only then, the highest cell for the
  // message. The scan compares floats with the smallest float t whose value
  // is >= the altitude: double(h) >= altitude <=> h >= t for every float h
  // (NaN: both false), twice the lanes of a comparison in double.
  float t = static_cast<float>(altitude_m);
  if (double(t) < altitude_m) t = std::nextafter(t, std::numeric_limits<float>::infinity());
  if (!kernels::any_at_or_above(scene.size(), scene.valid.data(), scene.elevation_m.data(), t))
    return;
  std::size_t worst = scene.size();
  float max_h = -std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < scene.size(); ++i) {
    if (scene.valid[i] && scene.elevation_m[i] > max_h) {
      max_h = scene.elevation_m[i];
      worst = i;
    }
  }
  if (worst == scene.size()) return;
  check_terrain_below_sensor(max_h, static_cast<int>(worst / static_cast<std::size_t>(scene.cols)),
                             static_cast<int>(worst % static_cast<std::size_t>(scene.cols)),
                             altitude_m, file);
}

void check_terrain_below_sensor(float max_h, int r, int c, double altitude_m,
                                const std::string& file) {
  if (r >= 0 && double(max_h) >= altitude_m) {
    // The whole scene's highest cell, not only the cells under the track:
    // a side-looking radar looks down on every cell it images.
    throw InputError(file, "track.altitude",
                     fmt::format("the terrain reaches {:.1f} m (scene row {}, column {}), at or "
                                 "above the sensor altitude {:.1f} m; expected an altitude above "
                                 "{:.1f} m, the scene's highest terrain (is the altitude's unit "
                                 "right: \"3000 m\" or \"10000 ft\"?)",
                                 max_h, r, c, altitude_m, max_h));
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
  // Checked before the cast: a spacing of 0.001 mm once wrapped to one line.
  g.lines = std::max<int>(
      1, static_cast<int>(checked_count(std::floor(track.length_m / g.line_spacing_m + 1e-6),
                                        kMaxItems, "", "azimuth_line_spacing", "azimuth lines")));

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

void SlarGeometry::allocate_samples() {
  const std::size_t n = static_cast<std::size_t>(lines) * static_cast<std::size_t>(samples);
  height_m.resize(n);
  slant_range_m.resize(n);
  incidence_rad.resize(n);
  local_incidence_rad.resize(n);
  area_m2.resize(n);
  range_near_end_m.resize(n);
  range_far_end_m.resize(n);
  category.resize(n);
  flags.resize(n);
}

void SlarGeometry::tally_flags(const Scene& scene) {
  const std::size_t n = flags.size();
  std::int64_t nodata = 0, shadow = 0, back = 0, layover = 0;
#pragma omp parallel for reduction(+ : nodata, shadow, back, layover) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint8_t f = flags[i];
    nodata += (f & sample_flag::kNoData) ? 1 : 0;
    shadow += (f & sample_flag::kShadow) ? 1 : 0;
    back += (f & sample_flag::kBackFacing) ? 1 : 0;
    layover += (f & sample_flag::kLayover) ? 1 : 0;
  }
  nodata_samples = nodata;
  shadow_samples = shadow;
  back_facing_samples = back;
  layover_samples = layover;
  nodata_cells = static_cast<std::int64_t>(std::count(scene.valid.begin(), scene.valid.end(), 0));
}

SlarLineSpan slar_line_span(const Scene& scene, const SlarGeometry& g, int line) {
  const Track& t = g.track;
  const auto [x0, y0] = t.world_from_along_cross(g.line_s_m(line), 0.0);
  SlarLineSpan span;
  span.grid = grid_line(scene, x0, y0, t.cross_x, t.cross_y, g.first_sample_u_m, g.sample_step_m);
  std::tie(span.begin, span.end) = inside_samples(span.grid, scene.rows, scene.cols, g.samples);
  // In front of the track only (slar_geometry_layout starts at u > 0 off
  // the axes; kept for any layout).
  while (span.begin < span.end && !(g.sample_u_m(span.begin) > 0.0)) ++span.begin;
  return span;
}

SlarGeometry compute_slar_geometry(const Scene& scene, const Track& track, double line_spacing_m,
                                   const std::string& radar_file) {
  scene.validate("scene");
  check_terrain_below_sensor(scene, track.altitude_m, radar_file);
  SlarGeometry g = slar_geometry_layout(scene, track, line_spacing_m);
  const bool along_y = nearly(std::abs(track.along_y), 1.0);

  // Along an axis the direct sampler reads the slope rasters; off the axes
  // the line sampler reads texels.
  SurfaceGradient grad;
  TerrainTexels tex;
  DirectSampler direct;
  if (g.direct_sampling) {
    grad = surface_gradient(scene);
    direct.scene = &scene;
    direct.grad = &grad;
    direct.cross_is_x = along_y;
    direct.u_grows_with_index = along_y ? track.cross_x > 0.0 : track.cross_y < 0.0;
  } else {
    tex = terrain_texels(scene);
  }

  g.allocate_samples();

  // Lines are independent: one line per iteration, the sampler copied per
  // thread (it holds only the current line's position), scratch per thread.
#pragma omp parallel firstprivate(direct)
  {
    LineScratch scratch(g);
#pragma omp for schedule(dynamic, 16)
    for (int line = 0; line < g.lines; ++line) {
      if (g.direct_sampling)
        fill_direct_line(g, direct, line, scratch);
      else
        fill_oblique_line(scene, tex, g, line, scratch);
    }
  }

  g.tally_flags(scene);
  return g;
}

}  // namespace ris
