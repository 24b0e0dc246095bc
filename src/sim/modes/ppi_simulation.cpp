#include "ris/sim/ppi_simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <variant>
#include <vector>

#include "ris/image/greytone.h"
#include "ris/image/greytone_image.h"
#include "ris/sim/point_target.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "sim/engine/slar_line_engine.h"
#include "sim/sources/polar_lines.h"
#include "sim/targets/ppi_ray_targets.h"

namespace ris {

namespace {

// Keeps lines [first, first + count) of an image.
SlarImage crop_lines(const SlarImage& in, int first, int count) {
  SlarImage out = in;
  out.lines = count;
  const std::size_t a = in.index(first, 0), n = static_cast<std::size_t>(count) * in.bins;
  const auto cut = [&](auto& v, const auto& src) {
    v.assign(src.begin() + static_cast<std::ptrdiff_t>(a),
             src.begin() + static_cast<std::ptrdiff_t>(a + n));
  };
  cut(out.mean_power_w, in.mean_power_w);
  cut(out.area_m2, in.area_m2);
  cut(out.mask, in.mask);
  cut(out.mapped_count, in.mapped_count);
  cut(out.visible_count, in.visible_count);
  return out;
}

// The padded rays' image through the line engine (the polar source), the
// rays' geometry kept (pg.rays allocated) and the targets added on their
// rays: what compute_ppi_geometry + point_returns_on_rays + form_slar_image
// give (tested: ppi_simulation_test.cpp).
SlarImage form_ppi_rays(const Scene& scene, PpiGeometry& pg, const Sigma0Lut& lut,
                        const SlarImagingParams& p, const std::string& radar_file,
                        const std::vector<PointTarget>& targets, PpiSimulation& sim) {
  SlarGeometry& g = pg.rays;
  g.allocate_samples();
  std::vector<double> base(targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t)
    base[t] = terrain_height_at(scene, targets[t].x_m, targets[t].y_m);
  std::vector<std::size_t> target_of;
  const std::vector<PointCandidate> candidates =
      detail::ray_candidates(targets, base, pg, target_of);
  detail::LinePointTargets on_rays(candidates);
  const detail::LineKeep keep{&g, nullptr, &on_rays};
  const TerrainTexels tex = terrain_texels(scene);
  const TwoWayGainTable gain2(p.elevation_gain, p.peak_gain, radar_file);
  SlarLineProfiles prof;
  prof.allocate(g.lines, p.range.count);
  const detail::SlarElementContext ctx = detail::element_context(p, gain2, lut, prof.bins);
  const detail::LineStages stages{ctx, LineLookFrame{}, true, p.range_window_bins, &keep};
  SlarLineCounts counts;
  detail::run_line_blocks(g, stages, 0, g.lines, 16, prof, counts, [&](detail::LineScratch&) {
    return detail::PolarThreadSource{scene, tex, pg, PpiRayScratch(g.samples)};
  });
  set_sample_counts(g, counts);
  g.nodata_cells = static_cast<std::int64_t>(std::count(scene.valid.begin(), scene.valid.end(), 0));
  check_swath_hits_scene(prof.samples_in_swath, p.range, counts, radar_file, "site.position");
  SlarImage img = slar_image_from_profiles(prof, p, g.line_spacing_m);
  // Each candidate's result (by_line[k].target: the candidate's index).
  std::vector<std::uint8_t> lit(candidates.size(), 0);
  std::vector<double> power(candidates.size(), 0.0);
  for (std::size_t k = 0; k < on_rays.by_line.size(); ++k) {
    lit[on_rays.by_line[k].target] = on_rays.lit[k];
    power[on_rays.by_line[k].target] = on_rays.power_w[k];
  }
  detail::fold_ray_targets(targets, candidates, target_of, lit, power, sim.point_returns,
                           img.point_power_w, sim.hidden_targets);
  return img;
}

}  // namespace

// Targets on every (padded) ray whose sector holds their azimuth.
std::vector<PointReturn> point_returns_on_rays(const std::vector<PointTarget>& targets,
                                               const Scene& scene, const PpiGeometry& pg,
                                               std::vector<std::string>& hidden) {
  std::vector<PointReturn> out;
  const SlarGeometry& g = pg.rays;
  const double H = pg.altitude_m;
  for (const PointTarget& t : targets) {
    const double dx = t.x_m - pg.site_x_m, dy = t.y_m - pg.site_y_m;
    const double u = std::hypot(dx, dy);
    const double alpha = std::atan2(dx, dy);
    const double h = terrain_height_at(scene, t.x_m, t.y_m) + t.height_m;
    bool any = false;
    for (int k = 0; k < g.lines; ++k) {
      if (!detail::azimuth_on_ray(pg, k, alpha)) continue;
      if (!(u > 0.0) || !point_lit_on_line(g, k, u, h)) continue;
      PointReturn r;
      r.line = k;
      r.along_m = alpha;
      r.slant_range_m = std::hypot(u, H - h);
      r.look_rad = std::atan2(u, H - h);
      r.rcs_m2 = t.rcs_m2;
      out.push_back(r);
      any = true;
    }
    if (!any) hidden.push_back(t.name);
  }
  return out;
}

PpiSimulation simulate_ppi(const Scene& scene, const RadarParams& radar_in,
                           const Sigma0Source& sigma0, const SlarOptions& options) {
  RIS_CHECK(radar_in.mode == RadarMode::ppi);
  PpiSimulation sim;
  sim.radar = radar_in;
  RadarParams& radar = sim.radar;
  sim.derived = derive(radar);
  const std::string backscatter_file = options.backscatter_name(sigma0);
  if (std::count(scene.valid.begin(), scene.valid.end(), 1) == 0) {
    throw InputError("scene", "", "the scene has no cell with data");
  }

  // The rays' layout (site, rays, samples); their geometry, slope and
  // shadow are formed ray by ray in the line engine.
  options.report("geometry", 0.0);
  sim.geometry = ppi_geometry_layout(scene, radar);
  PpiGeometry& pg = sim.geometry;

  options.report("backscatter", 0.3);
  RadiometrySetup rs = prepare_radiometry(scene, radar, sim.derived, sigma0, backscatter_file);
  sim.categories = rs.categories;
  sim.category_names = rs.category_names;
  sim.backscatter_description = rs.backscatter_description;

  // B-scope over the padded rays, smeared over the beamwidth, then cropped.
  options.report("geometry + image formation (line engine)", 0.4);
  check_point_targets_on_scene(options.targets, scene);
  SlarImagingParams& imaging = rs.imaging;
  sim.beam_rays = radar.azimuth_beamwidth_rad / pg.ray_spacing_rad;
  imaging.azimuth_window_lines = sim.beam_rays;
  SlarImage padded =
      form_ppi_rays(scene, pg, rs.lut, imaging, radar.source_file, options.targets, sim);
  apply_switch_corrections(padded, rs.terms);
  sim.bscope = crop_lines(padded, pg.pad, pg.scan_rays);

  sim.scope_grid =
      ppi_scope_grid(radar, sim.bscope.range, sim.bscope.lines, pg.altitude_m - pg.site_ground_m);
  return sim;
}

PpiPictures render_ppi(const PpiSimulation& sim, std::uint64_t seed) {
  const SlarImage& img = sim.bscope;
  PpiPictures pic;
  pic.seed = seed;
  std::vector<std::uint8_t> no_data(img.mask.size());
  for (std::size_t i = 0; i < no_data.size(); ++i)
    no_data[i] = (img.mask[i] & pixel_flag::kNoData) ? 1 : 0;
  GreytoneImage g = make_greytone_image(sim.radar, img.mean_power_w, img.lines, img.bins,
                                        img.range.near_m, img.range.bin_m, seed, no_data);
  pic.looks = std::move(g.looks_per_bin);
  pic.speckled_power_w = std::move(g.speckled_power_w);
  pic.bscope_grey = std::move(g.greytone);
  pic.reference_power_w = g.map.reference_power_w();
  pic.reference_greytone = g.map.reference_greytone();
  pic.greytones_per_decade = g.map.greytones_per_decade();
  pic.film_offset = g.map.film_offset();

  // The scope: the speckled B-scope scan-converted, the same greytone map.
  pic.scope_power_w = to_ppi_scope(pic.speckled_power_w, sim.scope_grid);
  pic.scope_mask = to_ppi_scope_nearest(img.mask, sim.scope_grid, pixel_flag::kNoData);
  std::vector<std::uint8_t> scope_no_data(pic.scope_mask.size());
  for (std::size_t i = 0; i < scope_no_data.size(); ++i)
    scope_no_data[i] = (pic.scope_mask[i] & pixel_flag::kNoData) ? 1 : 0;
  pic.scope_grey.resize(pic.scope_power_w.size());
  greytones(pic.scope_power_w, pic.scope_grey, g.map, scope_no_data);
  draw_range_rings(pic.scope_grey, sim.scope_grid, sim.radar.ppi.ring_spacing_m);
  return pic;
}

}  // namespace ris
