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

#include "ris/geometry/slar_geometry.h"
#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"
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
  std::vector<std::uint8_t> mask;          // rows x cols, scene_flag bits
  std::vector<float> local_incidence_deg;  // rows x cols; NaN where no data or not imaged
};

SceneGeometryMaps scene_geometry_maps(const Scene& scene, const SlarGeometry& geometry,
                                      const SlantRangeBins& bins);

// One cell's mask bits and local incidence (degrees, NaN when none) from the
// geometry sample it takes: shared by scene_geometry_maps and the fused paths
// (ris/sim/slar_line_blocks.h) so that they agree to the bit. far_m:
// bins.far_m().
inline void scene_map_cell(bool cell_valid, std::uint8_t sample_flags, float slant_range_m,
                           float local_incidence_rad, double near_m, double far_m,
                           std::uint8_t& mask, float& local_incidence_deg) {
  std::uint8_t f = cell_valid ? 0 : scene_flag::kNoData;
  const std::uint8_t sf = sample_flags;
  if (sf & sample_flag::kNoData) f |= scene_flag::kNoData;
  if (sf & sample_flag::kShadow) f |= scene_flag::kShadow;
  if (sf & sample_flag::kLayover) f |= scene_flag::kLayover;
  if (sf & sample_flag::kBackFacing) f |= scene_flag::kBackFacing;
  const double R = slant_range_m;
  const bool has_data = !(sf & (sample_flag::kNoData | sample_flag::kUnseen));
  if ((sf & sample_flag::kUnseen) || (has_data && !(R >= near_m && R < far_m))) {
    f |= scene_flag::kOutsideSwath;
  }
  local_incidence_deg = (has_data && !(f & scene_flag::kNoData))
                            ? static_cast<float>(rad_to_deg(local_incidence_rad))
                            : std::numeric_limits<float>::quiet_NaN();
  mask = f;
}

// std::round (half away from zero) for |x| < 2^62, inline: without SSE4.1
// std::round is a library call, and the fused oblique path rounds twice per
// cell. Exact: the truncation and x - trunc(x) are exact in double.
inline double round_half_away(double x) {
  const auto t = static_cast<double>(static_cast<std::int64_t>(x));
  const double d = x - t;
  return t + (d >= 0.5 ? 1.0 : 0.0) - (d <= -0.5 ? 1.0 : 0.0);
}

// The (line, sample) a cell takes: the nearest line and sample to its centre
// (false: none, the cell is outside the swath).
inline bool scene_cell_sample(const Scene& scene, const SlarGeometry& g, int r, int c, int& line,
                              int& sample) {
  const auto [x, y] = scene.cell_centre(r, c);
  const auto [s, u] = g.track.along_cross(x, y);
  const double lf = s / g.line_spacing_m - 0.5, jf = (u - g.first_sample_u_m) / g.sample_step_m;
  // Far outside the grid (or NaN): no line or sample, before any conversion.
  if (!(std::abs(lf) < 1e15 && std::abs(jf) < 1e15)) return false;
  const double l = round_half_away(lf);
  const double j = round_half_away(jf);
  if (!(l >= 0 && l < g.lines && j >= 0 && j < g.samples)) return false;
  line = static_cast<int>(l);
  sample = static_cast<int>(j);
  return true;
}

}  // namespace ris
