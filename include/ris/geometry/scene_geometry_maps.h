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

#include <cstdint>
#include <vector>

#include "ris/geometry/slar_geometry.h"
#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"

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

}  // namespace ris
