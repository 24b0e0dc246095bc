#include "ris/sim/slar_simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/image/greytone.h"
#include "ris/image/greytone_image.h"
#include "ris/image/greytone_terms.h"
#include "ris/image/thermal_noise.h"
#include "ris/sensor/elevation_gain.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/util/error.h"
#include "ris/util/float_select.h"

namespace ris {

namespace {

// The median of the cells with data (the upper one of an even count, as
// nth_element at n / 2), by a parallel radix select (ris/util/float_select.h).
double median_valid_elevation(const Scene& scene) {
  const auto keep = [&](std::size_t i) {
    return scene.valid[i] && std::isfinite(scene.elevation_m[i]);
  };
  const auto m = median_pair_float(scene.elevation_m, keep);
  return m ? m->second : 0.0;
}

}  // namespace

// A SAR resolution finer than the scene's sampling cannot show more detail
// than the scene holds; say what the image will look like instead.
std::vector<std::string> sar_resolution_warnings(const Scene& scene, const SlarGeometry& g,
                                                 const RadarParams& radar) {
  std::vector<std::string> out;
  if (radar.mode != RadarMode::sar) return out;
  const double az_m = radar.sar.azimuth_resolution_m;
  if (az_m < g.line_spacing_m) {
    out.push_back(fmt::format(
        "{}: the SAR azimuth resolution ({:.2f} m{}) is finer than the scene's azimuth sampling "
        "({:.2f} m, the azimuth line spacing): the image shows no detail finer than the scene's "
        "cells, point targets fall on the nearest line, and a coherent image's speckle has the "
        "grain of the scene's cells rather than of the resolution",
        radar.source_file, az_m,
        radar.sar.antenna_length_m > 0.0
            ? fmt::format(", half the {:.2f} m antenna", radar.sar.antenna_length_m)
            : std::string(),
        g.line_spacing_m));
  }
  // Ground-range resolution at far range (the finest on the ground).
  const double far_r = radar.far_slant_range_m;
  const double sin_far = std::sqrt(std::max(0.0, 1.0 - std::pow(g.altitude_m / far_r, 2)));
  const double ground_res_m = radar.sar.range_resolution_m / std::max(sin_far, 1e-6);
  const double cell_m = std::min(scene.dx_m, scene.dy_m);
  if (ground_res_m < cell_m) {
    out.push_back(fmt::format(
        "{}: the SAR ground-range resolution ({:.2f} m at far range, from {}) is finer than the "
        "scene's cells ({:.2f} m): the image shows no detail finer than the scene's cells, and a "
        "coherent image's speckle has the grain of the scene's cells rather than of the resolution",
        radar.source_file, ground_res_m,
        radar.sar.bandwidth_hz > 0.0
            ? fmt::format("c / (2 B) = {:.2f} m slant with B = {:.1f} MHz",
                          radar.sar.range_resolution_m, radar.sar.bandwidth_hz / 1e6)
            : fmt::format("range_resolution = {:.2f} m slant", radar.sar.range_resolution_m),
        cell_m));
  }
  return out;
}

SlarSimulation simulate_slar(const Scene& scene, const RadarParams& radar_in,
                             const Sigma0Source& sigma0, const SlarOptions& options) {
  SlarSimulation sim;
  sim.radar = radar_in;
  RadarParams& radar = sim.radar;
  sim.derived = derive(radar);
  const std::string backscatter_file = options.backscatter_name(sigma0);
  if (std::count(scene.valid.begin(), scene.valid.end(), 1) == 0) {
    throw InputError("scene", "", "the scene has no cell with data");
  }

  // Geometry (the seed's SLAR Geometry, Slope and Shadow).
  sim.track = resolve_track(radar.track, scene, radar.source_file);
  // A track along a grid axis runs fused per line (ris/sim/slar_line_blocks.h:
  // the same bytes without whole-scene geometry buffers) unless the caller
  // wants the per-sample geometry.
  const SlarGeometry layout = slar_geometry_layout(scene, sim.track, radar.azimuth_line_spacing_m);
  // The fused path forms SLAR and incoherent SAR images (range and azimuth
  // windows); the coherent SAR needs every element's power, point targets
  // the per-sample geometry.
  const bool fused_mode =
      radar.mode == RadarMode::slar || (radar.mode == RadarMode::sar && !radar.sar.coherent);
  const bool fused = !options.keep_geometry && fused_mode && options.targets.empty() &&
                     fused_slar_image_applies(scene, layout);
  if (fused) {
    scene.validate("scene");
    check_terrain_below_sensor(scene, sim.track.altitude_m, radar.source_file);
    sim.geometry = layout;
  } else {
    options.report("geometry", 0.0);
    sim.geometry =
        compute_slar_geometry(scene, sim.track, radar.azimuth_line_spacing_m, radar.source_file);
  }

  // sigma0 for every category the scene uses (and the reference's), the
  // switched-off factors at their reference values.
  options.report("backscatter", 0.3);
  RadiometrySetup rs = prepare_radiometry(scene, radar, sim.derived, sigma0, backscatter_file);
  sim.categories = rs.categories;
  sim.category_names = rs.category_names;
  sim.backscatter_description = rs.backscatter_description;
  SlarImagingParams& imaging = rs.imaging;

  options.report("image formation", 0.4);
  set_sar_windows(radar, sim.geometry.line_spacing_m, imaging);
  sim.warnings = sar_resolution_warnings(scene, sim.geometry, radar);
  check_point_targets_on_scene(options.targets, scene);
  if (fused) {
    options.report("geometry + image formation + scene maps (fused)", 0.4);
    sim.image = form_slar_image_fused(scene, sim.geometry, sim.scene_maps, rs.lut, imaging,
                                      radar.source_file);
  } else {
    sim.point_returns =
        point_returns_on_lines(options.targets, scene, sim.geometry, &sim.hidden_targets);
    imaging.point_returns = sim.point_returns;
    imaging.keep_element_power = radar.mode == RadarMode::sar && radar.sar.coherent;
    sim.image = form_slar_image(sim.geometry, rs.lut, imaging, radar.source_file);
  }
  std::tie(sim.range_corrected, sim.area_corrected) = apply_switch_corrections(sim.image, rs.terms);

  // SAR thermal noise: NESZ over the multilooked resolution cell.
  sim.noise_power_w = sar_noise_power_w(radar, imaging, sim.geometry.altitude_m);
  if (!sim.noise_power_w.empty()) add_noise_power(sim.image, sim.noise_power_w);

  // Products on the scene grid and the ground-range grid.
  if (!fused) {
    options.report("scene maps", 0.8);
    sim.scene_maps = scene_geometry_maps(scene, sim.geometry, sim.image.range);
  }
  options.report("ground-range grid", 0.9);
  const double h_ref =
      options.reference_height_m ? *options.reference_height_m : median_valid_elevation(scene);
  sim.ground_grid =
      ground_range_grid(sim.image.range, sim.geometry.altitude_m, h_ref, sim.image.line_spacing_m);
  return sim;
}

SlarPictures render_slar(const SlarSimulation& sim, std::uint64_t seed,
                         std::span<const float> coherent_intensity) {
  const SlarImage& img = sim.image;
  SlarPictures pic;
  pic.seed = seed;
  std::vector<std::uint8_t> no_data(img.mask.size());
  for (std::size_t i = 0; i < no_data.size(); ++i)
    no_data[i] = (img.mask[i] & pixel_flag::kNoData) ? 1 : 0;

  // Fading keyed by (seed, pixel) and greytones (equation 15), the reference
  // from the mean power so the grey scale does not depend on the seed.
  const bool coherent = !coherent_intensity.empty();
  RadarParams radar = sim.radar;
  if (coherent) radar.switches.fading = false;  // the speckle is in the intensity
  GreytoneImage g = make_greytone_image(radar, img.mean_power_w, img.lines, img.bins,
                                        img.range.near_m, img.range.bin_m, seed, no_data);
  if (coherent) {
    RIS_CHECK(coherent_intensity.size() == img.mean_power_w.size());
    g.speckled_power_w.assign(coherent_intensity.begin(), coherent_intensity.end());
    greytones(g.speckled_power_w, g.greytone, g.map, no_data);
  }
  pic.looks = std::move(g.looks_per_bin);
  pic.speckled_power_w = std::move(g.speckled_power_w);
  pic.slant_grey = std::move(g.greytone);
  pic.reference_power_w = g.map.reference_power_w();
  pic.reference_greytone = g.map.reference_greytone();
  pic.greytones_per_decade = g.map.greytones_per_decade();
  pic.film_offset = g.map.film_offset();

  // Ground range: the speckled power resampled, then the same greytone map.
  const GroundRangeGrid& grid = sim.ground_grid;
  pic.ground_power_w = to_ground_range(pic.speckled_power_w, img.lines, img.range, grid);
  pic.ground_mask =
      to_ground_range_nearest(img.mask, img.lines, img.range, grid, pixel_flag::kNoData);
  std::vector<std::uint8_t> ground_no_data(pic.ground_mask.size());
  for (std::size_t i = 0; i < ground_no_data.size(); ++i)
    ground_no_data[i] = (pic.ground_mask[i] & pixel_flag::kNoData) ? 1 : 0;
  pic.ground_grey.resize(pic.ground_power_w.size());
  greytones(pic.ground_power_w, pic.ground_grey, g.map, ground_no_data);
  return pic;
}

}  // namespace ris
