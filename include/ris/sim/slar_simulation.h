// A whole SLAR simulation, in two stages (DESIGN.md: each arrow is plain
// data, so the cheap end can be re-run without the expensive start):
//
//   simulate_slar   scene + radar + sigma0 -> geometry, mean-power image,
//                   masks, scene-grid maps (the seed's SLAR Geometry, Slope
//                   and Shadow programs)
//   render_slar     mean power -> speckle -> greytones, slant and ground range
//                   (the seed's SLAR Greytone, run as often as wanted)
//
// The greytone switches of equation 15 act as ris/image/greytone_terms.h
// prescribes: switched-off radar-equation factors are replaced by the
// reference cell's while forming the image (transmit power, wavelength,
// antenna gain, backscatter) or corrected per pixel afterwards (range, area);
// k and M in the greytone map; fading by applying speckle or not.
//
// SAR stripmap (radar.mode == sar, MODEL.md section 3) runs the same stages:
// the azimuth window is the constant multilooked resolution L_a rho_a instead
// of w(R) = R phi, the range window L_r rho_r over bins of the configured
// sampling, and NESZ noise is added to the mean power
// (ris/image/thermal_noise.h). The coherent SAR option is rendered by
// ris/sim/sar_coherent.h from the same simulation.
//
// Example:
//   ris::SlarSimulation sim = ris::simulate_slar(scene, radar, *sigma0, {});
//   ris::SlarPictures pic = ris::render_slar(sim, 42);
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/geometry/scene_geometry_maps.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/image/ground_range.h"
#include "ris/image/radiometric_calibration.h"
#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sensor/radar_params.h"
#include "ris/sensor/track.h"
#include "ris/sim/point_target.h"
#include "ris/util/default_init_allocator.h"

namespace ris {

struct SlarOptions {
  // The backscatter file, named in error messages (a category it lacks).
  std::string backscatter_file;
  // Ground-range reference height h_ref; default: the median elevation of
  // the scene's cells with data.
  std::optional<double> reference_height_m;
  // Called at the start of each stage (name, fraction of the run done).
  std::function<void(std::string_view, double)> progress;
  // Keep the per-sample geometry arrays in SlarSimulation::geometry. Every
  // run goes per line through the line engine (ris/sim/slar_line_blocks.h);
  // by default `geometry` holds only its layout and counts (the products
  // need no more), unless the run needs the arrays itself (the coherent
  // SAR; lines not one per cell row or column). The images are the same
  // bytes either way.
  bool keep_geometry = false;
  // Point scatterers added to the scene (ris/sim/point_target.h); checked to
  // lie on the scene.
  std::vector<PointTarget> targets;
  // Lines per block of the line engine (0: the engine's choice). Any value
  // gives the same bytes (the scene-query stage's determinism tests vary it).
  int engine_block_lines = 0;
  // Channels of one polarimetric SAR (ris/sim/sar_quad_pol.h): every
  // channel coherent and keeping its element powers, the point targets the
  // first channel's (their power is polarisation-free).
  bool polarimetric_channels = false;

  // The backscatter source's name for messages: backscatter_file, or the
  // source's own description.
  std::string backscatter_name(const Sigma0Source& sigma0) const {
    return backscatter_file.empty() ? sigma0.description() : backscatter_file;
  }
  // Reports a stage to `progress`, when set.
  void report(std::string_view stage, double fraction) const {
    if (progress) progress(stage, fraction);
  }
};

struct SlarSimulation {
  RadarParams radar;  // as used (reference sigma0 resolved)
  RadarDerived derived;
  Track track;
  SlarGeometry geometry;
  SlarImage image;  // mean power with the switched factors applied
  SceneGeometryMaps scene_maps;
  GroundRangeGrid ground_grid;
  std::string backscatter_description;
  std::vector<std::uint16_t> categories;  // used by cells with data
  std::vector<std::string> category_names;
  bool range_corrected = false;  // range switch off: pixels carry R_1^-4
  bool area_corrected = false;   // area switch off: pixels carry dA_1
  // Point targets as seen (and the names of those beyond the swath or in
  // shadow).
  std::vector<PointReturn> point_returns;
  std::vector<std::string> hidden_targets;
  // SAR: thermal noise power added per range bin (empty without NESZ).
  std::vector<double> noise_power_w;
  // The radiometric calibration of the image over the ground-range
  // reference height (ris/image/radiometric_calibration.h); empty when the
  // range or area switch is off (the pixels then carry the reference's
  // factor, not this radar's) and in runs that do not form it.
  SlantCalibration calibration;
  // Conditions worth a user's attention that are not errors (printed by the
  // command, recorded in metadata.json).
  std::vector<std::string> warnings;
  // The same printed by the command and in the run's summary, but not in
  // metadata.json: added later (issue 38's swath coverage), they leave the
  // products of runs that were valid before their bytes.
  std::vector<std::string> summary_warnings;
  // Both, for stderr and the run's summary.
  std::vector<std::string> reported_warnings() const {
    std::vector<std::string> all = warnings;
    all.insert(all.end(), summary_warnings.begin(), summary_warnings.end());
    return all;
  }
};

// Throws InputError for bad input (terrain at or above the sensor, a swath
// that misses the scene, a category without backscatter, ...).
// SAR: warnings when the resolution is finer than the scene holds (azimuth
// below the line spacing, ground range below the cells), each saying what the
// image will look like instead; empty otherwise. `scene`: its grid only.
std::vector<std::string> sar_resolution_warnings(const Scene& scene, const SlarGeometry& geometry,
                                                 const RadarParams& radar);

SlarSimulation simulate_slar(const Scene& scene, const RadarParams& radar,
                             const Sigma0Source& sigma0, const SlarOptions& options = {});

struct SlarPictures {
  std::uint64_t seed = 0;
  // Written in full by render_slar's parallel loop (no zero fill first).
  UninitVector<float> speckled_power_w;    // lines x bins (mean power when fading is off)
  UninitVector<std::uint8_t> slant_grey;   // lines x bins
  UninitVector<float> ground_power_w;      // lines x ground_grid.count, speckled
  UninitVector<std::uint8_t> ground_mask;  // lines x ground_grid.count, pixel_flag bits
  UninitVector<std::uint8_t> ground_grey;
  std::vector<double> looks;  // N per range bin
  double reference_power_w = 0.0;
  double reference_greytone = 0.0;
  double greytones_per_decade = 0.0;
  double film_offset = 0.0;
};

// coherent_intensity (optional, lines x bins): the coherent SAR's intensity
// (ris/sim/sar_coherent.h), which then stands in for the fading of the mean
// power (the speckle is already in it); the grey scale still comes from the
// mean power.
SlarPictures render_slar(const SlarSimulation& sim, std::uint64_t seed,
                         std::span<const float> coherent_intensity = {});

}  // namespace ris
