#include "ris/geometry/ppi_geometry.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include "ris/geometry/line_scan.h"
#include "ris/geometry/terrain_line.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/scene/geo_frame.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"
#include "ris/util/units.h"

namespace ris {

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

const char* site_key(const RadarParams& radar) {
  return radar.ppi.site_latlon_deg ? "site.latlon" : "site.position";
}

}  // namespace

RadarParams ppi_site_on_scene(const RadarParams& radar, const Scene& grid) {
  RadarParams r = radar;
  if (!r.ppi.site_latlon_deg) return r;
  if (grid.crs_wkt.empty()) {
    throw InputError(radar.source_file, "site.latlon",
                     "the site is in latitude/longitude but the scene has no CRS (import a DEM "
                     "with ris scene import, or give position in scene metres)");
  }
  const GeoFrame frame(grid.crs_wkt, radar.source_file);
  const auto [lat, lon] = *r.ppi.site_latlon_deg;
  std::tie(r.ppi.site_x_m, r.ppi.site_y_m) = frame.scene_from_lonlat(lon, lat);
  return r;
}

void check_ppi_site_inside(const Scene& grid, const RadarParams& radar) {
  const PpiParams& p = radar.ppi;
  const auto [x0, y1] = grid.world_from_grid(0.0, 0.0);
  const auto [x1, y0] = grid.world_from_grid(grid.cols, grid.rows);
  if (!(p.site_x_m >= x0 && p.site_x_m <= x1 && p.site_y_m >= y0 && p.site_y_m <= y1)) {
    throw InputError(radar.source_file, site_key(radar),
                     fmt::format("the radar site ({:.1f}, {:.1f}) m is outside the scene, which "
                                 "spans x {:.1f} to {:.1f} m and y {:.1f} to {:.1f} m",
                                 p.site_x_m, p.site_y_m, x0, x1, y0, y1));
  }
}

double check_ppi_site_terrain(const RadarParams& radar, const TerrainSample& site) {
  const PpiParams& p = radar.ppi;
  if (!site.valid) {
    throw InputError(radar.source_file, site_key(radar),
                     fmt::format("the radar site ({:.1f}, {:.1f}) m lies on no-data cells of the "
                                 "scene; expected a site on terrain with data",
                                 p.site_x_m, p.site_y_m));
  }
  const double ground_m = site.height_m;
  if (p.altitude_m && !(*p.altitude_m > ground_m)) {
    throw InputError(radar.source_file, "site.altitude",
                     fmt::format("the antenna altitude {:.1f} m is at or below the terrain at the "
                                 "site ({:.1f} m); expected an altitude above the terrain (or give "
                                 "height, the antenna above the ground)",
                                 *p.altitude_m, ground_m));
  }
  return ground_m;
}

PpiGeometry ppi_rays_layout(const Scene& grid, const RadarParams& radar, double site_ground_m,
                            float h_min_m) {
  RIS_CHECK(radar.mode == RadarMode::ppi);
  const PpiParams& p = radar.ppi;
  PpiGeometry pg;
  pg.site_ground_m = site_ground_m;
  pg.site_x_m = p.site_x_m;
  pg.site_y_m = p.site_y_m;
  pg.altitude_m = p.altitude_m ? *p.altitude_m : pg.site_ground_m + *p.height_above_ground_m;
  const double H = pg.altitude_m;

  // Rays: the sector's, plus the beam's half-width (and one) at each end.
  pg.ray_spacing_rad = p.ray_spacing_rad;
  pg.scan_rays = std::max(1, static_cast<int>(std::lround(p.scan_width_rad / p.ray_spacing_rad)));
  pg.pad = static_cast<int>(std::ceil(0.5 * radar.azimuth_beamwidth_rad / p.ray_spacing_rad)) + 1;
  pg.first_azimuth_rad = p.scan_start_rad + (0.5 - pg.pad) * p.ray_spacing_rad;

  // Samples: out to the far range over the lowest terrain, or the farthest
  // scene corner, whichever is nearer.
  const double d_low = H - double(h_min_m);
  const double u_far =
      d_low > 0.0 && radar.far_slant_range_m > d_low
          ? std::sqrt(radar.far_slant_range_m * radar.far_slant_range_m - d_low * d_low)
          : radar.far_slant_range_m;
  double u_corner = 0.0;
  for (int r : {0, grid.rows})
    for (int c : {0, grid.cols}) {
      const auto [x, y] = grid.world_from_grid(c, r);
      u_corner = std::max(u_corner, std::hypot(x - p.site_x_m, y - p.site_y_m));
    }
  SlarGeometry& g = pg.rays;
  g.altitude_m = H;
  g.direct_sampling = false;
  g.lines = pg.scan_rays + 2 * pg.pad;
  g.line_spacing_m = 0.0;
  g.sample_step_m = 0.5 * std::min(grid.dx_m, grid.dy_m);
  g.first_sample_u_m = 0.5 * g.sample_step_m;
  g.samples = std::max(1, static_cast<int>(std::ceil(std::min(u_far, u_corner) / g.sample_step_m)));
  g.track.altitude_m = H;
  return pg;
}

PpiGeometry ppi_geometry_layout(const Scene& scene, const RadarParams& radar_in) {
  scene.validate("scene");
  const RadarParams radar = ppi_site_on_scene(radar_in, scene);
  RIS_CHECK(radar.mode == RadarMode::ppi);
  const PpiParams& p = radar.ppi;
  check_ppi_site_inside(scene, radar);
  const double ground_m = check_ppi_site_terrain(
      radar, bilinear_terrain_sample(scene, nullptr, p.site_x_m, p.site_y_m));
  float h_min = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < scene.size(); ++i)
    if (scene.valid[i]) h_min = std::min(h_min, scene.elevation_m[i]);
  PpiGeometry pg = ppi_rays_layout(scene, radar, ground_m, h_min);
  const SlarGeometry& g = pg.rays;

  // The rays' geometry before it is allocated (ris/util/resource_guard.h):
  // 31 bytes a sample, as a SLAR line's; a fine ray spacing multiplies it.
  require_memory(checked_mul(checked_mul(g.lines, g.samples, radar.source_file, "scan.ray_spacing"),
                             31, radar.source_file, "scan.ray_spacing"),
                 radar.source_file, "scan.ray_spacing",
                 fmt::format("the geometry of {} rays x {} samples", g.lines, g.samples));
  return pg;
}

GridLine ppi_ray_line(const Scene& grid, const PpiGeometry& pg, int ray) {
  const double alpha = pg.azimuth_rad(ray);
  return grid_line(grid, pg.site_x_m, pg.site_y_m, std::sin(alpha), std::cos(alpha),
                   pg.rays.first_sample_u_m, pg.rays.sample_step_m);
}

PpiRayScratch::PpiRayScratch(int samples)
    : height(static_cast<std::size_t>(samples)),
      dz_dx(height.size()),
      dz_dy(height.size()),
      category(height.size()),
      terrain_flags(height.size()) {}

void ppi_ray_geometry(const Scene& scene, const TerrainTexels& tex, const PpiGeometry& pg, int ray,
                      const PpiRayOut& out, PpiRayScratch& s) {
  const GridLine line = ppi_ray_line(scene, pg, ray);
  const auto [begin, end] = inside_samples(line, scene.rows, scene.cols, pg.rays.samples);
  const SampledTerrain terrain{s.height.data(), s.dz_dx.data(), s.dz_dy.data(), s.category.data(),
                               s.terrain_flags.data()};
  sample_terrain_line(tex, line, begin, end, terrain);
  ppi_ray_geometry_from_terrain(pg, ray, begin, end, terrain, out);
}

void ppi_ray_geometry_from_terrain(const PpiGeometry& pg, int ray, int begin, int end,
                                   const SampledTerrain& s, const PpiRayOut& out) {
  const SlarGeometry& g = pg.rays;
  const double H = pg.altitude_m;
  const double alpha = pg.azimuth_rad(ray);
  const double look_x = std::sin(alpha), look_y = std::cos(alpha);
  for (int j = 0; j < g.samples; ++j) {
    const std::size_t i = static_cast<std::size_t>(j);
    const double u = g.sample_u_m(j);
    const bool inside = j >= begin && j < end;
    const auto o = static_cast<std::size_t>(inside ? j - begin : 0);
    std::uint8_t f = inside ? s.flags[o] : sample_flag::kUnseen;
    if (f != 0) {
      out.height_m[i] = out.slant_range_m[i] = out.incidence_rad[i] = kNaN;
      out.local_incidence_rad[i] = out.area_m2[i] = kNaN;
      out.range_near_end_m[i] = out.range_far_end_m[i] = kNaN;
      out.category[i] = 0;
      out.flags[i] = f;
      out.dh_du[i] = 0.0f;
      continue;
    }
    TerrainSample ts;
    ts.inside = ts.valid = true;
    ts.height_m = s.height_m[o];
    ts.dz_dx = s.dz_dx[o];
    ts.dz_dy = s.dz_dy[o];
    ts.category = s.category[o];
    const SampleLook look = look_at(ts, u, H, look_x, look_y);
    if (look.cos_local <= 0.0) f |= sample_flag::kBackFacing;
    out.height_m[i] = ts.height_m;
    out.slant_range_m[i] = static_cast<float>(look.slant_range_m);
    out.incidence_rad[i] = static_cast<float>(look.incidence_rad);
    out.local_incidence_rad[i] = static_cast<float>(local_incidence_rad(look));
    // The annular sector u dalpha x step, tilted.
    out.area_m2[i] =
        static_cast<float>(u * pg.ray_spacing_rad * g.sample_step_m * look.normal_length);
    out.dh_du[i] = static_cast<float>(look.dh_du);
    out.category[i] = ts.category;
    out.flags[i] = f;
  }
  const LineSamples ls{g.samples,    g.first_sample_u_m, g.sample_step_m,      H,
                       out.height_m, out.slant_range_m,  out.range_near_end_m, out.range_far_end_m,
                       out.dh_du,    out.flags};
  line_element_ends(ls);
  mark_shadow_and_layover(ls);
}

PpiGeometry compute_ppi_geometry(const Scene& scene, const RadarParams& radar) {
  PpiGeometry pg = ppi_geometry_layout(scene, radar);
  SlarGeometry& g = pg.rays;
  g.allocate_samples();
  const TerrainTexels tex = terrain_texels(scene);
  // Rays are independent: one per iteration, scratch per thread. Along a ray
  // the line sampler (ris/geometry/terrain_line.h) gives the terrain of the
  // samples within the scene; the rest are unseen.
#pragma omp parallel
  {
    PpiRayScratch scratch(g.samples);
    std::vector<float> dh_du(static_cast<std::size_t>(g.samples));
#pragma omp for schedule(dynamic, 16)
    for (int ray = 0; ray < g.lines; ++ray) {
      const std::size_t base = g.index(ray, 0);
      const PpiRayOut out{&g.height_m[base],        &g.slant_range_m[base],
                          &g.incidence_rad[base],   &g.local_incidence_rad[base],
                          &g.area_m2[base],         &g.range_near_end_m[base],
                          &g.range_far_end_m[base], &g.category[base],
                          &g.flags[base],           dh_du.data()};
      ppi_ray_geometry(scene, tex, pg, ray, out, scratch);
    }
  }
  g.tally_flags(scene);
  return pg;
}

}  // namespace ris
