// A slant-range image projected back onto the scene grid (map geometry), so
// that it overlays the DEM in a GIS: "geocoding" by the range-Doppler
// relation of a real-aperture SLAR (MODEL.md section 2).
//
// Each scene cell with data, at (x, y, h), takes the image pixel it maps to:
// the azimuth line of its along-track position s (line k stands for
// s in [k ds, (k + 1) ds), as in ris/geometry/scene_geometry_maps.h) and the
// range bin of its slant range R = sqrt(u^2 + (H - h)^2) from the track
// (bin k: R_near + k dr <= R < R_near + (k + 1) dr). Cells without data, behind
// the track (u <= 0) or outside the image are NaN. A cell in radar shadow
// takes whatever its pixel holds (the power of the nearer terrain that
// shares its range, or nothing); layover cells share their pixel's power.
// This is the terrain-corrected "backward" geocoding of SAR processors,
// without interpolation (nearest pixel).
//
// Example:
//   std::vector<float> map = ris::geocode_slant_image(scene, sim.track, sim.image,
//                                                     pictures.speckled_power_w);
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"
#include "ris/sensor/track.h"

namespace ris {

// The image pixel (line, bin) of the scene cell (row, col) at elevation
// elevation_m (a cell with data); false when it is behind the track or
// outside the image. `image` gives only its layout (lines, bins, range, line
// spacing). The one formula of the functions below and of the streamed
// geocoding (ris/sim/slar_stream.h).
bool geocode_pixel(const Scene& grid, const Track& track, const SlarImage& image, int row, int col,
                   float elevation_m, int& line, int& bin);

// slant_values: lines x bins (the image's layout), e.g. power in W.
// Returns rows x cols on the scene grid, NaN where no pixel applies.
std::vector<float> geocode_slant_image(const Scene& scene, const Track& track,
                                       const SlarImage& image, std::span<const float> slant_values);

// The same for 8-bit greytones; cells without a pixel get `fill` (0).
std::vector<std::uint8_t> geocode_slant_grey(const Scene& scene, const Track& track,
                                             const SlarImage& image,
                                             std::span<const std::uint8_t> slant_grey,
                                             std::uint8_t fill = 0);

}  // namespace ris
