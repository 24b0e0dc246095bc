// The stage path, the reference the line engine (ris/sim/slar_line_blocks.h)
// is tested against: a whole SLAR / SAR run as separate stages over
// whole-run buffers, as simulate_slar ran them before every run went through
// the engine: compute_slar_geometry (every sample's geometry), point targets
// placed on the finished geometry (point_returns_on_lines), form_slar_image
// (with each element's power for the coherent SAR) and scene_geometry_maps.
// The stages around them (radiometry, SAR windows, switch corrections,
// noise) are the ones every driver shares (ris/sim/slar_run_setup.h).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ris/geometry/ppi_geometry.h"
#include "ris/geometry/scene_geometry_maps.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/image/ground_range.h"
#include "ris/image/slar_image.h"
#include "ris/sim/point_target.h"
#include "ris/sim/ppi_simulation.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_run_setup.h"
#include "ris/sim/slar_simulation.h"

namespace ris::test {

// simulate_slar by the stages: the same SlarSimulation (geometry always
// kept; element power for the coherent SAR).
inline SlarSimulation simulate_slar_by_stages(const Scene& scene, const RadarParams& radar_in,
                                              const Sigma0Source& sigma0,
                                              const SlarOptions& options = {}) {
  SlarSimulation sim;
  sim.radar = radar_in;
  RadarParams& radar = sim.radar;
  sim.derived = derive(radar);
  sim.track = resolve_track(radar.track, scene, radar.source_file);
  sim.geometry =
      compute_slar_geometry(scene, sim.track, radar.azimuth_line_spacing_m, radar.source_file);
  RadiometrySetup rs =
      prepare_radiometry(scene, radar, sim.derived, sigma0, options.backscatter_name(sigma0));
  complete_slar_setup(sim, rs, scene);
  check_point_targets_on_scene(options.targets, scene);
  sim.point_returns =
      point_returns_on_lines(options.targets, scene, sim.geometry, &sim.hidden_targets);
  rs.imaging.point_returns = sim.point_returns;
  rs.imaging.keep_element_power = radar.mode == RadarMode::sar && radar.sar.coherent;
  sim.image = form_slar_image(sim.geometry, rs.lut, rs.imaging, radar.source_file);
  finish_slar_image(sim, sim.image, rs.terms);
  sim.scene_maps = scene_geometry_maps(scene, sim.geometry, sim.image.range);
  // The ground-range grid at the median height of the cells with data (the
  // upper one of an even count), as simulate_slar.
  double h_ref = 0.0;
  if (options.reference_height_m) {
    h_ref = *options.reference_height_m;
  } else {
    std::vector<float> h;
    for (std::size_t i = 0; i < scene.size(); ++i) {
      if (scene.valid[i] && std::isfinite(scene.elevation_m[i])) h.push_back(scene.elevation_m[i]);
    }
    if (!h.empty()) {
      std::nth_element(h.begin(), h.begin() + static_cast<std::ptrdiff_t>(h.size() / 2), h.end());
      h_ref = h[h.size() / 2];
    }
  }
  sim.ground_grid =
      ground_range_grid(sim.image.range, sim.geometry.altitude_m, h_ref, sim.image.line_spacing_m);
  return sim;
}

// simulate_ppi by the stages: compute_ppi_geometry (every ray's geometry),
// point_returns_on_rays on it, form_slar_image over the padded rays, the
// switch corrections, the sector's rays cropped.
inline PpiSimulation simulate_ppi_by_stages(const Scene& scene, const RadarParams& radar_in,
                                            const Sigma0Source& sigma0,
                                            const SlarOptions& options = {}) {
  PpiSimulation sim;
  sim.radar = radar_in;
  RadarParams& radar = sim.radar;
  sim.derived = derive(radar);
  sim.geometry = compute_ppi_geometry(scene, radar);
  const PpiGeometry& pg = sim.geometry;
  RadiometrySetup rs =
      prepare_radiometry(scene, radar, sim.derived, sigma0, options.backscatter_name(sigma0));
  sim.categories = rs.categories;
  sim.category_names = rs.category_names;
  sim.backscatter_description = rs.backscatter_description;
  check_point_targets_on_scene(options.targets, scene);
  sim.point_returns = point_returns_on_rays(options.targets, scene, pg, sim.hidden_targets);
  sim.beam_rays = radar.azimuth_beamwidth_rad / pg.ray_spacing_rad;
  rs.imaging.azimuth_window_lines = sim.beam_rays;
  rs.imaging.point_returns = sim.point_returns;
  SlarImage padded = form_slar_image(pg.rays, rs.lut, rs.imaging, radar.source_file);
  apply_switch_corrections(padded, rs.terms);
  // Rays pad .. pad + scan_rays - 1.
  SlarImage& b = sim.bscope;
  b = padded;
  b.lines = pg.scan_rays;
  const std::size_t a = padded.index(pg.pad, 0);
  const std::size_t n = static_cast<std::size_t>(pg.scan_rays) * static_cast<std::size_t>(b.bins);
  const auto cut = [&](auto& v, const auto& src) {
    v.assign(src.begin() + static_cast<std::ptrdiff_t>(a),
             src.begin() + static_cast<std::ptrdiff_t>(a + n));
  };
  cut(b.mean_power_w, padded.mean_power_w);
  cut(b.area_m2, padded.area_m2);
  cut(b.mask, padded.mask);
  cut(b.mapped_count, padded.mapped_count);
  cut(b.visible_count, padded.visible_count);
  return sim;
}

}  // namespace ris::test
