// The SLAR geometry stage: the terrain sampled along zero-Doppler lines, with
// per sample slant range, incidence, local incidence, true facet area, cast
// shadow, back-facing and layover (MODEL.md section 2).
//
// Azimuth line k lies at along-track position s_k = (k + 1/2) * line_spacing
// from the track start; sample j of every line at cross-track ground distance
// u_j = first_sample_u_m + j * sample_step_m. Two samplers, chosen once per
// run:
//   - direct: the track runs along a grid axis; each sample is one scene cell
//     (its centre's u, its elevation and category), the line taking the
//     nearest row (or column) of cells; sample_step_m is the cell size across
//     track.
//   - bilinear: any other heading; elevation and slope are interpolated
//     bilinearly, the category is the nearest cell's, at a step of half the
//     smaller cell size (ris/geometry/terrain_line.h). A sample touching a
//     no-data cell is no data. Only the samples within the scene
//     (slar_line_span) are sampled and scanned; the rest are unseen.
// The slope comes from ris/geometry/surface_gradient.h (central differences).
//
// The result is plain data (line-major arrays of lines x samples), so image
// formation, speckle and greytone can be re-run on it without recomputing it.
//
// Example:
//   ris::Track track = ris::resolve_track(radar.track, scene, radar.source_file);
//   ris::SlarGeometry g = ris::compute_slar_geometry(scene, track, 0.0, radar.source_file);
//   float r_m = g.slant_range_m[g.index(line, sample)];
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "ris/geometry/line_scan.h"  // sample_flag, sample_visible
#include "ris/geometry/terrain_line.h"
#include "ris/scene/scene.h"
#include "ris/sensor/track.h"

namespace ris {

struct SlarGeometry {
  Track track;
  double altitude_m = 0.0;  // H
  bool direct_sampling = false;

  int lines = 0;
  int samples = 0;  // per line
  double line_spacing_m = 0.0;
  double sample_step_m = 0.0;
  double first_sample_u_m = 0.0;

  // Per sample, index(line, sample); NaN (or 0 for integers) where unseen or
  // no data, except flags.
  std::vector<float> height_m;             // h above the datum
  std::vector<float> slant_range_m;        // R = sqrt(u^2 + (H - h)^2)
  std::vector<float> incidence_rad;        // flat-earth incidence = look angle from nadir
  std::vector<float> local_incidence_rad;  // acos(n . l); > pi/2 when back-facing
  std::vector<float> area_m2;              // true (tilted) area of the element
  // Slant range of the element's two ends along the line, at u - step/2 and
  // u + step/2. The element is the polyline from its near end through its
  // centre to its far end; the end heights are the means with the
  // neighbouring samples (or the local slope's extrapolation where a
  // neighbour has no data). A step in the terrain is thus shared by the two
  // cells beside it, and its range extent is the terrain's, not a tilted
  // facet's overshoot.
  std::vector<float> range_near_end_m;
  std::vector<float> range_far_end_m;
  std::vector<std::uint16_t> category;
  std::vector<std::uint8_t> flags;

  // Counts over all samples.
  std::int64_t nodata_samples = 0;  // samples inside the scene on no-data cells
  std::int64_t shadow_samples = 0;
  std::int64_t back_facing_samples = 0;
  std::int64_t layover_samples = 0;
  std::int64_t nodata_cells = 0;  // scene cells without data

  std::size_t index(int line, int sample) const {
    return static_cast<std::size_t>(line) * static_cast<std::size_t>(samples) +
           static_cast<std::size_t>(sample);
  }
  double line_s_m(int line) const { return (line + 0.5) * line_spacing_m; }
  double sample_u_m(int sample) const { return first_sample_u_m + sample * sample_step_m; }

  // Sizes the per-sample arrays for lines x samples (SLAR lines and PPI rays).
  void allocate_samples();
  // Sets the *_samples counts from the flags and nodata_cells from the scene.
  void tally_flags(const Scene& scene);
};

// Throws InputError naming radar_file and key "track.altitude" when valid terrain
// reaches the sensor altitude (compute_slar_geometry's check).
void check_terrain_below_sensor(const Scene& scene, double altitude_m,
                                const std::string& radar_file);
// The same given the highest valid cell (the first in row-major order among
// equals; a streamed scene, ris/sim/slar_stream.h); row < 0: no valid cell.
void check_terrain_below_sensor(float max_elevation_m, int row, int col, double altitude_m,
                                const std::string& radar_file);

// The geometry's layout (track, lines, samples, spacing, first sample; no
// per-sample arrays, counts 0) as compute_slar_geometry sets it: it needs
// only the scene's grid, not its data (used by the fused and streamed
// pipelines, ris/sim/slar_line_blocks.h).
SlarGeometry slar_geometry_layout(const Scene& scene, const Track& track, double line_spacing_m);

// A line of a heading off the grid axes (!direct_sampling) in grid
// coordinates, and its samples [begin, end) that are within the scene and in
// front of the track (u > 0); the others are unseen. Shared by the stage path
// (compute_slar_geometry) and the fused one (ris/sim/slar_line_blocks.h), so
// that both sample and scan the same samples.
struct SlarLineSpan {
  GridLine grid;
  int begin = 0, end = 0;
};
SlarLineSpan slar_line_span(const Scene& scene, const SlarGeometry& g, int line);

// Computes the geometry. line_spacing_m <= 0 means one scene cell (the cell
// size along the track's nearer grid axis). Throws InputError naming
// radar_file and key "altitude" when valid terrain reaches the sensor
// altitude.
SlarGeometry compute_slar_geometry(const Scene& scene, const Track& track, double line_spacing_m,
                                   const std::string& radar_file);

}  // namespace ris
