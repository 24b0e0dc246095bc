// The geometry stage's flags and local incidence back on the scene grid, for
// GeoTIFF products georeferenced like the scene.
//
// Each scene cell takes the geometry sample nearest its centre (for a track
// along a grid axis with one-cell lines, the cell's own sample).
//
// Mask bits (scene_flag):
//   1  shadow         cast shadow
//   2  layover        in the SNAP layover zone
//   4  no data        the scene has no data here
//   8  back-facing    the facet faces away from the radar (cos theta_l <= 0)
//   16 outside swath  not imaged: beyond the track's ends, behind the track
//                     (u <= 0), or slant range outside [R_near, R_far)
//
// Example:
//   ris::SceneGeometryMaps m = ris::scene_geometry_maps(scene, geometry, img.range);
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "ris/geometry/slant_range_bins.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/scene/scene.h"
#include "ris/util/default_init_allocator.h"
#include "ris/util/units.h"

namespace ris {

namespace scene_flag {
inline constexpr std::uint8_t kShadow = 1;
inline constexpr std::uint8_t kLayover = 2;
inline constexpr std::uint8_t kNoData = 4;
inline constexpr std::uint8_t kBackFacing = 8;
inline constexpr std::uint8_t kOutsideSwath = 16;
}  // namespace scene_flag

struct SceneGeometryMaps {
  UninitVector<std::uint8_t> mask;          // rows x cols, scene_flag bits
  UninitVector<float> local_incidence_deg;  // rows x cols; NaN where no data or not imaged
};

SceneGeometryMaps scene_geometry_maps(const Scene& scene, const SlarGeometry& geometry,
                                      const SlantRangeBins& bins);

// A geometry sample's part of the maps of the cells that take it: its mask
// bits (scene_flag) and local incidence in degrees (NaN when the sample has
// no data or is unseen). far_m: bins.far_m().
struct SampleMapValue {
  std::uint8_t mask = 0;
  float local_incidence_deg = 0.0f;
};

inline SampleMapValue scene_map_sample(std::uint8_t sample_flags, float slant_range_m,
                                       float local_incidence_rad, double near_m, double far_m) {
  SampleMapValue v;
  const std::uint8_t sf = sample_flags;
  std::uint8_t f = 0;
  if (sf & sample_flag::kNoData) f |= scene_flag::kNoData;
  if (sf & sample_flag::kShadow) f |= scene_flag::kShadow;
  if (sf & sample_flag::kLayover) f |= scene_flag::kLayover;
  if (sf & sample_flag::kBackFacing) f |= scene_flag::kBackFacing;
  const double R = slant_range_m;
  const bool has_data = !(sf & (sample_flag::kNoData | sample_flag::kUnseen));
  if ((sf & sample_flag::kUnseen) || (has_data && !(R >= near_m && R < far_m))) {
    f |= scene_flag::kOutsideSwath;
  }
  v.mask = f;
  v.local_incidence_deg = has_data ? static_cast<float>(rad_to_deg(local_incidence_rad))
                                   : std::numeric_limits<float>::quiet_NaN();
  return v;
}

// A cell's maps from its sample's part: a cell without data adds kNoData and
// has no local incidence.
inline void scene_map_from_sample(bool cell_valid, const SampleMapValue& v, std::uint8_t& mask,
                                  float& local_incidence_deg) {
  mask = static_cast<std::uint8_t>(v.mask | (cell_valid ? 0 : scene_flag::kNoData));
  local_incidence_deg =
      cell_valid ? v.local_incidence_deg : std::numeric_limits<float>::quiet_NaN();
}

// One cell's mask bits and local incidence (degrees, NaN when none) from the
// geometry sample it takes: shared by scene_geometry_maps and the fused paths
// (ris/sim/slar_line_blocks.h) so that they agree to the bit. far_m:
// bins.far_m().
inline void scene_map_cell(bool cell_valid, std::uint8_t sample_flags, float slant_range_m,
                           float local_incidence_rad, double near_m, double far_m,
                           std::uint8_t& mask, float& local_incidence_deg) {
  scene_map_from_sample(
      cell_valid, scene_map_sample(sample_flags, slant_range_m, local_incidence_rad, near_m, far_m),
      mask, local_incidence_deg);
}

// std::round (half away from zero) for |x| < 2^62, inline: without SSE4.1
// std::round is a library call, and the fused oblique path rounds twice per
// cell. Exact: the truncation and x - trunc(x) are exact in double.
inline double round_half_away(double x) {
  const auto t = static_cast<double>(static_cast<std::int64_t>(x));
  const double d = x - t;
  return t + (d >= 0.5 ? 1.0 : 0.0) - (d <= -0.5 ? 1.0 : 0.0);
}

// Which (line, sample) each cell takes: the nearest line and sample to its
// centre. The fractional line and sample indices are affine in the cell's
// row and column,
//   line_f = (line0 + r line_dr) + c line_dc,  sample_f likewise,
// evaluated in exactly this order by everyone (scene_geometry_maps, the fused
// oblique path's per-block scatter), so that a row's base is computed once
// and every path assigns every cell the same sample.
struct CellSampleFrame {
  double line0 = 0.0, line_dr = 0.0, line_dc = 0.0;        // at cell (0, 0); per row; per column
  double sample0 = 0.0, sample_dr = 0.0, sample_dc = 0.0;  // the same for the sample index
  int lines = 0, samples = 0;

  double line_f(double row_base, int c) const { return row_base + c * line_dc; }
  double line_row_base(int r) const { return line0 + r * line_dr; }
  double sample_f(double row_base, int c) const { return row_base + c * sample_dc; }
  double sample_row_base(int r) const { return sample0 + r * sample_dr; }
};

// line_f = s / line_spacing - 1/2 and sample_f = (u - first_sample_u) /
// sample_step at the cell's centre (s, u: along- and cross-track, track.h).
CellSampleFrame cell_sample_frame(const Scene& scene, const SlarGeometry& g);

// Rounds (half away from zero) a cell's fractional line or sample index;
// false when outside [0, n) (or not finite, or far outside).
inline bool nearest_index(double f, int n, int& index) {
  if (!(std::abs(f) < 1e15)) return false;
  const double k = round_half_away(f);
  if (!(k >= 0 && k < n)) return false;
  index = static_cast<int>(k);
  return true;
}

// The (line, sample) cell (r, c) takes (false: none, the cell is outside the
// swath).
inline bool cell_sample(const CellSampleFrame& f, int r, int c, int& line, int& sample) {
  return nearest_index(f.line_f(f.line_row_base(r), c), f.lines, line) &&
         nearest_index(f.sample_f(f.sample_row_base(r), c), f.samples, sample);
}

}  // namespace ris
