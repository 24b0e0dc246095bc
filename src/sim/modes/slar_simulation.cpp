#include "ris/sim/slar_simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/geometry/swath_coverage.h"
#include "ris/image/greytone.h"
#include "ris/image/greytone_image.h"
#include "ris/image/greytone_terms.h"
#include "ris/image/speckle.h"
#include "ris/sensor/elevation_gain.h"
#include "ris/sensor/track_view.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_channels.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/sim/slar_run_setup.h"
#include "ris/util/error.h"
#include "ris/util/float_select.h"
#include "ris/util/resource_guard.h"

namespace ris {

namespace {

// The median of the cells with data (the upper one of an even count, as
// nth_element at n / 2), by a parallel radix select (ris/util/float_select.h).
double median_valid_elevation(const Scene& scene) {
  const std::uint8_t* const valid = scene.valid.data();
  const float* const h = scene.elevation_m.data();
  const auto keep = [=](std::size_t i) { return (valid[i] != 0) & std::isfinite(h[i]); };
  const auto m = median_pair_float(scene.elevation_m, keep);
  return m ? m->second : 0.0;
}

// The run's memory before any large array is made: the per-sample geometry
// when kept (7 floats, a category and flags: 31 bytes a sample); per
// slant-range pixel the mean power, speckled power (floats), mask and
// greytone (10 bytes); per ground-range pixel power, mask and greytone (6).
// The ground grid's spacing is the line spacing, so a 1 cm azimuth line
// spacing once made a ground image of 10^11 pixels.
// channels: images of that many channels (ris/sim/slar_channels.h).
void require_run_memory(const SlarGeometry& g, bool keeps_geometry, const SlantRangeBins& range,
                        double h_ref_m, const std::string& radar_file, int channels) {
  const std::string key = "azimuth_line_spacing";
  // Terrain above the sensor or no range bins: reported by the checks that
  // follow, with their own messages.
  GroundRangeGrid ground;
  if (h_ref_m < g.altitude_m && range.count > 0 && g.line_spacing_m > 0.0) {
    ground = ground_range_grid(range, g.altitude_m, h_ref_m, g.line_spacing_m);
  }
  const std::int64_t samples = checked_mul(g.lines, g.samples, radar_file, key);
  const std::int64_t slant = checked_mul(g.lines, range.count, radar_file, key);
  const std::int64_t ground_px = checked_mul(g.lines, ground.count, radar_file, key);
  std::int64_t bytes =
      checked_mul(checked_add(checked_mul(slant, 10, radar_file, key),
                              checked_mul(ground_px, 6, radar_file, key), radar_file, key),
                  channels, radar_file, key);
  if (keeps_geometry)
    bytes = checked_add(bytes, checked_mul(samples, 31, radar_file, key), radar_file, key);
  require_memory(bytes, radar_file, key,
                 fmt::format("an image of {} lines x {} range bins ({} samples, {} ground-range "
                             "pixels a line)",
                             g.lines, range.count, g.samples, ground.count));
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

namespace {

// Channel c's geometry must be channel 0's (ris/sim/slar_channels.h): its
// track, lines and range bins.
void check_same_geometry(const SlarSimulation& first, const SlarSimulation& other,
                         const SlarGeometry& first_layout, const SlarGeometry& layout,
                         std::size_t c) {
  const std::string& file = other.radar.source_file;
  const auto refuse = [&](const std::string& key, const std::string& what) {
    throw InputError(file, key,
                     fmt::format("channel {} of a multi-channel run must share channel 0's ({}) "
                                 "geometry: {}",
                                 c, first.radar.source_file, what));
  };
  if (other.radar.mode != first.radar.mode) refuse("mode", "a different mode");
  if (layout.lines != first_layout.lines || layout.samples != first_layout.samples ||
      layout.altitude_m != first_layout.altitude_m ||
      layout.line_spacing_m != first_layout.line_spacing_m ||
      layout.sample_step_m != first_layout.sample_step_m ||
      layout.first_sample_u_m != first_layout.first_sample_u_m ||
      layout.track.cross_x != first_layout.track.cross_x ||
      layout.track.cross_y != first_layout.track.cross_y) {
    refuse("track", "a different track or azimuth line spacing");
  }
  if (other.derived.near_slant_range_m != first.derived.near_slant_range_m ||
      other.derived.range_bin_m != first.derived.range_bin_m ||
      other.derived.range_bins != first.derived.range_bins) {
    refuse("sweep_delay", "different range bins (sweep delay, pulse width or sampling)");
  }
}

}  // namespace

SlarSimulation simulate_slar(const Scene& scene, const RadarParams& radar,
                             const Sigma0Source& sigma0, const SlarOptions& options) {
  const SlarChannel one{radar, &sigma0, ""};
  return std::move(simulate_slar_channels(scene, std::span(&one, 1), options).front());
}

std::vector<SlarSimulation> simulate_slar_channels(const Scene& scene,
                                                   std::span<const SlarChannel> channels,
                                                   const SlarOptions& options) {
  if (channels.empty()) throw InputError("", "channels", "a run needs at least one channel");
  const std::size_t nc = channels.size();
  std::vector<SlarSimulation> sims(nc);
  std::vector<std::string> backscatter_files(nc);
  for (std::size_t c = 0; c < nc; ++c) {
    sims[c].radar = channels[c].radar;
    sims[c].derived = derive(sims[c].radar);
    backscatter_files[c] = channels[c].backscatter_file.empty()
                               ? options.backscatter_name(*channels[c].sigma0)
                               : channels[c].backscatter_file;
  }
  SlarSimulation& sim = sims.front();
  RadarParams& radar = sim.radar;
  if (std::find(scene.valid.begin(), scene.valid.end(), 1) == scene.valid.end()) {
    throw InputError("scene", "", "the scene has no cell with data");
  }
  // Geometry (the seed's SLAR Geometry, Slope and Shadow), radiometry and
  // image formation run per line through the line engine
  // (ris/sim/slar_line_blocks.h), without whole-scene geometry buffers
  // unless the run keeps the per-sample geometry: when the caller asks, for
  // the coherent SAR (its range compression reads every element's range and
  // power), and when the lines are not one per cell row or column (the
  // scene maps are then made from it).
  sim.track = resolve_track(radar.track, scene, radar.source_file);
  check_scene_in_view(radar.track, sim.track, scene, radar.source_file);
  const SlarGeometry layout = slar_geometry_layout(scene, sim.track, radar.azimuth_line_spacing_m);
  const bool coherent = radar.mode == RadarMode::sar && radar.sar.coherent;
  for (std::size_t c = 1; c < nc; ++c) {
    SlarSimulation& other = sims[c];
    other.track = resolve_track(other.radar.track, scene, other.radar.source_file);
    const SlarGeometry lc =
        slar_geometry_layout(scene, other.track, other.radar.azimuth_line_spacing_m);
    check_same_geometry(sim, other, layout, lc, c);
    if (options.polarimetric_channels) {
      RIS_CHECK(coherent && other.radar.sar.coherent);
    } else if (coherent || (other.radar.mode == RadarMode::sar && other.radar.sar.coherent)) {
      throw InputError(other.radar.source_file, "sar.coherent",
                       "the coherent SAR is a single-channel run for now; run each channel "
                       "alone, or set coherent = false");
    }
    if (!options.targets.empty() && !options.polarimetric_channels) {
      throw InputError(other.radar.source_file, "targets",
                       "point targets are placed in single-channel runs only for now; run each "
                       "channel alone with its targets");
    }
    other.geometry = layout;  // the layout: the counts follow from channel 0's run
  }
  const bool keep_geometry =
      options.keep_geometry || coherent || !fused_slar_image_applies(scene, layout);
  // Memory before any large array or long loop (ris/util/resource_guard.h).
  const double h_ref =
      options.reference_height_m ? *options.reference_height_m : median_valid_elevation(scene);
  require_run_memory(layout, keep_geometry,
                     SlantRangeBins{sim.derived.near_slant_range_m, sim.derived.range_bin_m,
                                    sim.derived.range_bins},
                     h_ref, radar.source_file, static_cast<int>(nc));
  scene.validate("scene");
  check_terrain_below_sensor(scene, sim.track.altitude_m, radar.source_file);
  sim.geometry = layout;
  // sigma0 for every category the scene uses (and the reference's), the
  // switched-off factors at their reference values; each channel's own.
  options.report("backscatter", 0.3);
  std::vector<RadiometrySetup> rs;
  rs.reserve(nc);
  // The scene's categories are read once (a pass over the scene), by the
  // first channel.
  rs.push_back(
      prepare_radiometry(scene, radar, sim.derived, *channels[0].sigma0, backscatter_files[0]));
  for (std::size_t c = 1; c < nc; ++c) {
    rs.push_back(prepare_radiometry(rs[0].categories, sims[c].radar, sims[c].derived,
                                    *channels[c].sigma0, backscatter_files[c]));
  }
  // SAR windows, resolution warnings and thermal noise (as a streamed run).
  for (std::size_t c = 0; c < nc; ++c) complete_slar_setup(sims[c], rs[c], scene);
  // Less than half of the scene in the swath: said (the channels share it).
  if (auto w = swath_coverage_warning(swath_coverage(sim.track, scene, rs[0].imaging.range, h_ref)))
    sim.summary_warnings.push_back(*w);
  check_point_targets_on_scene(options.targets, scene);
  options.report("geometry + image formation + scene maps (line engine)", 0.4);
  SlarEngineKeep keep;
  keep.geometry = keep_geometry;
  keep.element_power = coherent;
  keep.targets = &options.targets;
  keep.point_returns = &sim.point_returns;
  keep.hidden_targets = &sim.hidden_targets;
  keep.block_lines = options.engine_block_lines;
  std::vector<SlarImageChannel> more;
  for (std::size_t c = 1; c < nc; ++c) {
    more.push_back(
        {&rs[c].lut, &rs[c].imaging, &sims[c].image, coherent && options.polarimetric_channels});
  }
  sim.image = form_slar_image_fused(scene, sim.geometry, sim.scene_maps, rs[0].lut, rs[0].imaging,
                                    radar.source_file, keep, more);
  for (std::size_t c = 1; c < nc; ++c) {
    // The geometry's counts and scene maps are the first channel's.
    SlarGeometry& g = sims[c].geometry;
    g.nodata_samples = sim.geometry.nodata_samples;
    g.shadow_samples = sim.geometry.shadow_samples;
    g.back_facing_samples = sim.geometry.back_facing_samples;
    g.layover_samples = sim.geometry.layover_samples;
    g.nodata_cells = sim.geometry.nodata_cells;
    sims[c].scene_maps = sim.scene_maps;
  }
  // Switch corrections and SAR thermal noise (as a streamed run's blocks).
  for (std::size_t c = 0; c < nc; ++c) finish_slar_image(sims[c], sims[c].image, rs[c].terms);
  // Products on the ground-range grid (its reference height, the median
  // elevation, was found before the run: part of the set-up's stage).
  for (SlarSimulation& s : sims) {
    s.ground_grid =
        ground_range_grid(s.image.range, s.geometry.altitude_m, h_ref, s.image.line_spacing_m);
  }
  // Each channel's calibration over the same reference height (per range
  // bin: cheap), unless a switched-off factor put the reference's in.
  for (std::size_t c = 0; c < nc; ++c) {
    if (sims[c].range_corrected || sims[c].area_corrected) continue;
    sims[c].calibration = slant_calibration(rs[c].imaging, sims[c].image.line_spacing_m,
                                            sims[c].geometry.altitude_m, h_ref);
  }
  return sims;
}

SlarPictures render_slar(const SlarSimulation& sim, std::uint64_t seed,
                         std::span<const float> coherent_intensity) {
  const SlarImage& img = sim.image;
  const int lines = img.lines, bins = img.bins;
  const std::size_t n_pix = static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins);
  RIS_CHECK(img.mean_power_w.size() == n_pix && img.mask.size() == n_pix);
  SlarPictures pic;
  pic.seed = seed;

  // Greytones (equation 15) with the reference from the mean power, so the
  // grey scale does not depend on the seed (make_greytone_image's map).
  const bool coherent = !coherent_intensity.empty();
  if (coherent) RIS_CHECK(coherent_intensity.size() == n_pix);
  RadarParams radar = sim.radar;
  if (coherent) radar.switches.fading = false;  // the speckle is in the intensity
  const GreytoneMap map = make_greytone_map_for_median(
      radar, radar.reference.automatic
                 ? median_valid_power_w(img.mean_power_w, img.mask, pixel_flag::kNoData)
                 : std::numeric_limits<double>::quiet_NaN());
  pic.looks = looks_per_bin(radar, bins, img.range.near_m, img.range.bin_m);
  pic.reference_power_w = map.reference_power_w();
  pic.reference_greytone = map.reference_greytone();
  pic.greytones_per_decade = map.greytones_per_decade();
  pic.film_offset = map.film_offset();
  std::optional<FadingField> fading;
  if (radar.switches.fading) fading.emplace(pic.looks, radar.fading, seed);

  // Per line, in one pass (every step is per pixel, keyed by (seed, bin,
  // line) for the fading, so the bytes are those of the whole-image steps:
  // make_greytone_image, to_ground_range, to_ground_range_nearest,
  // greytones): the speckled power (NaN for no data), its greytones, the
  // ground-range power, mask and greytones. One parallel region instead of
  // seven, and each line stays in cache between the steps.
  const GroundRangeResampler ground(img.range, sim.ground_grid);
  const std::size_t cols = static_cast<std::size_t>(ground.columns());
  const std::size_t n_ground = static_cast<std::size_t>(lines) * cols;
  pic.speckled_power_w.resize(n_pix);
  pic.slant_grey.resize(n_pix);
  pic.ground_power_w.resize(n_ground);
  pic.ground_mask.resize(n_ground);
  pic.ground_grey.resize(n_ground);
  constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
  const auto b_count = static_cast<std::size_t>(bins);
  // Dynamic blocks of lines: on a shared machine, when one thread loses its
  // core the other takes its lines instead of waiting at the barrier (each
  // line is independent: the same bytes for any schedule).
#pragma omp parallel for schedule(dynamic, 16)
  for (int line = 0; line < lines; ++line) {
    const std::size_t at = static_cast<std::size_t>(line) * b_count;
    const std::uint8_t* mask = img.mask.data() + at;
    float* speckled = pic.speckled_power_w.data() + at;
    if (coherent) {
      std::copy_n(coherent_intensity.data() + at, b_count, speckled);
    } else {
      const float* mean = img.mean_power_w.data() + at;
      for (std::size_t b = 0; b < b_count; ++b)
        speckled[b] = (mask[b] & pixel_flag::kNoData) ? kNaN : mean[b];
      if (fading) fading->apply_line(speckled, line);
    }
    // The line's bins from its first to its last number: outside them every
    // pixel is NaN, whose greytone is the no-data one whatever the mask, and
    // so are the ground pixels whose two bins lie outside (an oblique track's
    // lines are about half no data at their ends). Steps below skip them:
    // the same bytes.
    std::size_t first = 0, end = b_count;
    while (first < end && std::isnan(speckled[first])) ++first;
    while (end > first && std::isnan(speckled[end - 1])) --end;
    std::uint8_t* slant_grey = pic.slant_grey.data() + at;
    std::fill(slant_grey, slant_grey + first, std::uint8_t{0});
    greytone_line(map, speckled + first, mask + first, pixel_flag::kNoData, end - first,
                  slant_grey + first);
    std::fill(slant_grey + end, slant_grey + b_count, std::uint8_t{0});
    // Ground range: the speckled power resampled, the mask's nearest bin,
    // then the same greytone map.
    const std::size_t g_at = static_cast<std::size_t>(line) * cols;
    float* ground_power = pic.ground_power_w.data() + g_at;
    std::uint8_t* ground_mask = pic.ground_mask.data() + g_at;
    std::uint8_t* ground_grey = pic.ground_grey.data() + g_at;
    const GroundRangeResampler::Columns run =
        ground.columns_within(static_cast<int>(first), static_cast<int>(end));
    ground.resample_line(speckled, ground_power, run);
    ground.nearest_line(mask, ground_mask, pixel_flag::kNoData);
    std::fill(ground_grey, ground_grey + run.begin, std::uint8_t{0});
    greytone_line(map, ground_power + run.begin, ground_mask + run.begin, pixel_flag::kNoData,
                  run.end - run.begin, ground_grey + run.begin);
    std::fill(ground_grey + run.end, ground_grey + cols, std::uint8_t{0});
  }
  return pic;
}

}  // namespace ris
