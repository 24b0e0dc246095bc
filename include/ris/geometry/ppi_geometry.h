// The PPI geometry stage: the terrain sampled along rays from a radar site
// (MODEL.md section 2, "PPI"). Each ray is a vertical half-plane at azimuth
// alpha (clockwise from north, scene +y); along it the line geometry of
// SLAR holds with u the ground distance from the site, so the per-sample
// quantities, the element ends and the shadow and layover scans are the
// shared ones (ris/geometry/line_scan.h), and the rays are stored as the
// lines of a SlarGeometry, so image formation (ris/image/slar_image.h)
// serves PPI unchanged.
//
// Rays: the scan sector [start, start + width) is split into whole rays
// ray_spacing apart (at most half the azimuth beamwidth), ray k centred at
// alpha_k = start + (k + 1/2) spacing. `pad` rays are added before the first
// and after the last so that the azimuth smearing over the beamwidth sees the
// ground the beam covers beyond the sector's edge rays (for a full circle,
// the rays on the other side of north). Samples: u_j = (j + 1/2) step, step =
// half the smaller cell size, bilinear elevation and slope, nearest
// category (ris/geometry/terrain_sample.h), out to the far slant range over
// the lowest terrain or the scene's farthest corner.
//
// The element of sample j on ray k is the annular sector u_j dalpha x step:
// its horizontal area grows with u, so summing rays over the beamwidth gives
// the ground arc u phi that the beam covers.
//
// Example:
//   ris::PpiGeometry g = ris::compute_ppi_geometry(scene, radar);
//   double alpha = g.azimuth_rad(k);  // ray k of g.rays (0 .. g.rays.lines - 1)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ris/geometry/slar_geometry.h"
#include "ris/geometry/terrain_line.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"

namespace ris {

struct PpiGeometry {
  // Lines = rays, including the padding. Unused SLAR fields: track,
  // line_spacing_m (0; the rays' spacing is ray_spacing_rad).
  SlarGeometry rays;
  double site_x_m = 0.0, site_y_m = 0.0;
  double site_ground_m = 0.0;      // terrain height at the site
  double altitude_m = 0.0;         // antenna above the datum, H
  double first_azimuth_rad = 0.0;  // centre of ray 0 (a padding ray)
  double ray_spacing_rad = 0.0;
  int pad = 0;        // padding rays at each end
  int scan_rays = 0;  // rays in the sector: rays pad .. pad + scan_rays - 1
  double azimuth_rad(int ray) const { return first_azimuth_rad + ray * ray_spacing_rad; }
};

// Throws InputError naming radar.source_file for a site off the scene or on
// no data (key "site.position"), an antenna at or below the terrain at the
// site (key "site.altitude"), or a range window that misses the scene.
PpiGeometry compute_ppi_geometry(const Scene& scene, const RadarParams& radar);

// compute_ppi_geometry's parts, for a run that forms the rays one at a time
// (the line engine's polar source, ris/sim/ppi_simulation.h): the layout
// (site, rays, samples; no per-sample arrays, counts 0; the same checks and
// the memory check of the rays' geometry), and one ray's geometry.
PpiGeometry ppi_geometry_layout(const Scene& scene, const RadarParams& radar);

// One ray's per-sample outputs, pg.rays.samples values each (dh_du: the
// slope along the ray, the scans' input).
struct PpiRayOut {
  float* height_m;
  float* slant_range_m;
  float* incidence_rad;
  float* local_incidence_rad;
  float* area_m2;
  float* range_near_end_m;
  float* range_far_end_m;
  std::uint16_t* category;
  std::uint8_t* flags;
  float* dh_du;
};
// A thread's scratch for ppi_ray_geometry (the ray's sampled terrain).
struct PpiRayScratch {
  std::vector<float> height, dz_dx, dz_dy;
  std::vector<std::uint16_t> category;
  std::vector<std::uint8_t> terrain_flags;
  explicit PpiRayScratch(int samples);
};
// The geometry of ray `ray` of layout pg (ppi_geometry_layout), the shadow
// and layover scans included, as compute_ppi_geometry fills it; tex:
// terrain_texels(scene).
void ppi_ray_geometry(const Scene& scene, const TerrainTexels& tex, const PpiGeometry& pg, int ray,
                      const PpiRayOut& out, PpiRayScratch& s);

// The steps of the two above that do not need the scene in memory, for a run
// that reads it a window at a time (ris/sim/ppi_stream.h); `grid` is the
// scene's grid (its arrays are not read).
//
// The radar with a [site] latlon placed on the scene's grid.
RadarParams ppi_site_on_scene(const RadarParams& radar, const Scene& grid);
// Throws InputError (key site.position / site.latlon) for a site off the scene.
void check_ppi_site_inside(const Scene& grid, const RadarParams& radar);
// site: the terrain at the site (bilinear_terrain_sample). Returns its
// height; throws InputError for a site on no data or an antenna at or below it.
double check_ppi_site_terrain(const RadarParams& radar, const TerrainSample& site);
// The rays and samples (site on the scene, its terrain height and the lowest
// elevation of the cells with data given; no memory check).
PpiGeometry ppi_rays_layout(const Scene& grid, const RadarParams& radar, double site_ground_m,
                            float h_min_m);
// Ray `ray`'s samples in the scene's grid coordinates (the line sampler's
// GridLine; inside_samples gives those within the scene).
GridLine ppi_ray_line(const Scene& grid, const PpiGeometry& pg, int ray);
// ppi_ray_geometry after the terrain is sampled: terrain[j - begin] is
// sample j's in [begin, end), the others are unseen.
void ppi_ray_geometry_from_terrain(const PpiGeometry& pg, int ray, int begin, int end,
                                   const SampledTerrain& terrain, const PpiRayOut& out);

}  // namespace ris
