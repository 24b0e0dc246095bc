// A whole PPI simulation (MODEL.md section 2, "PPI"), in the two stages of
// the SLAR one (ris/sim/slar_simulation.h):
//
//   simulate_ppi  scene + radar + sigma0 -> ray geometry (per-ray shadow and
//                 layover), the B-scope's mean power (rays x slant-range bins,
//                 smeared in azimuth over the beamwidth), its mask
//   render_ppi    mean power -> speckle -> greytones; the B-scope and the
//                 scan-converted PPI scope (ris/image/ppi_scope.h), range rings
//
// The rays run through the line engine (ris/sim/slar_line_blocks.h) as its
// lines, each ray's geometry made by the polar source (ppi_ray_geometry)
// and kept; the B-scope is formed as ris/image/slar_image.h forms an image,
// with an azimuth window of beamwidth / ray spacing rays, over the sector plus
// padding rays (so the beam's edges see the ground beyond the sector's edge
// rays, and a full circle wraps through north), then cropped to the sector.
// The greytone switches act as for SLAR.
//
// Example:
//   ris::PpiSimulation sim = ris::simulate_ppi(scene, radar, *sigma0, {});
//   ris::PpiPictures pic = ris::render_ppi(sim, 42);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/geometry/ppi_geometry.h"
#include "ris/image/ppi_scope.h"
#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

struct PpiSimulation {
  RadarParams radar;  // as used (reference sigma0 resolved)
  RadarDerived derived;
  PpiGeometry geometry;  // rays including padding
  SlarImage bscope;      // sector rays x bins (row k: ray centred at start + (k + 1/2) spacing)
  PpiScopeGrid scope_grid;
  std::string backscatter_description;
  std::vector<std::uint16_t> categories;
  std::vector<std::string> category_names;
  std::vector<PointReturn> point_returns;  // on the padded rays
  std::vector<std::string> hidden_targets;
  std::vector<std::string> warnings;
  double beam_rays = 0.0;  // azimuth window: beamwidth / ray spacing
};

// Throws InputError for bad input (a site off the scene or below the
// terrain, a range window that misses the scene, a category without
// backscatter, a target off the scene, ...). options.reference_height_m is
// unused (the ground presentation is over the site's terrain).
PpiSimulation simulate_ppi(const Scene& scene, const RadarParams& radar, const Sigma0Source& sigma0,
                           const SlarOptions& options = {});

// The targets on every (padded) ray of a computed geometry
// (compute_ppi_geometry) whose sector holds their azimuth and whose terrain
// leaves them lit, in target and ray order; `hidden` receives the names of
// the targets seen on no ray. The stage path's rule, which simulate_ppi
// applies ray by ray in the line engine (the reference it is tested
// against).
std::vector<PointReturn> point_returns_on_rays(const std::vector<PointTarget>& targets,
                                               const Scene& scene, const PpiGeometry& pg,
                                               std::vector<std::string>& hidden);

struct PpiPictures {
  std::uint64_t seed = 0;
  std::vector<float> speckled_power_w;    // B-scope, rays x bins
  std::vector<std::uint8_t> bscope_grey;  // rays x bins
  std::vector<float> scope_power_w;       // scope, size x size, speckled; NaN outside
  std::vector<std::uint8_t> scope_mask;   // pixel_flag bits; kNoData outside
  std::vector<std::uint8_t> scope_grey;   // with range rings when configured
  std::vector<double> looks;
  double reference_power_w = 0.0;
  double reference_greytone = 0.0;
  double greytones_per_decade = 0.0;
  double film_offset = 0.0;
};

PpiPictures render_ppi(const PpiSimulation& sim, std::uint64_t seed);

}  // namespace ris
