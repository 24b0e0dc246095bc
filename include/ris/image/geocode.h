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
// nearest pixel by default; bilinear (gdalwarp's `-r bilinear`) on request
// interpolates between the four pixel centres around the cell's position,
// weights renormalised over those with data (as GDAL's warper does).
//
// Example:
//   std::vector<float> map = ris::geocode_slant_image(scene, sim.track, sim.image,
//                                                     pictures.speckled_power_w);
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "ris/image/slar_image.h"
#include "ris/scene/scene.h"
#include "ris/sensor/track.h"

namespace ris {

// How a cell takes its value from the slant image: the pixel it falls in
// (`near`, the default: the products' bytes), or bilinear between the four
// pixel centres around it (`bilinear`). Named as gdalwarp's -r values.
enum class GeocodeResampling { nearest, bilinear };

// Parses "near" or "bilinear" (gdalwarp's names); throws InputError naming
// `source` and `key` otherwise.
GeocodeResampling parse_geocode_resampling(const std::string& text, const std::string& source,
                                           const std::string& key);

// The continuous image position of the scene cell (row, col) at elevation
// elevation_m, in GDAL's pixel / line coordinates (0 at the top-left corner
// of pixel (0, 0); pixel centres at k + 0.5): line = s / ds,
// bin = (R - R_near) / dr. False behind the track (u <= 0).
bool geocode_position(const Scene& grid, const Track& track, const SlarImage& image, int row,
                      int col, float elevation_m, double& line, double& bin);

// The image pixel (line, bin) of the scene cell (row, col) at elevation
// elevation_m (a cell with data); false when it is behind the track or
// outside the image. `image` gives only its layout (lines, bins, range, line
// spacing). The one formula of the functions below and of the streamed
// geocoding (ris/sim/slar_stream.h).
bool geocode_pixel(const Scene& grid, const Track& track, const SlarImage& image, int row, int col,
                   float elevation_m, int& line, int& bin);

// slant_values: lines x bins (the image's layout), e.g. power in W.
// Returns rows x cols on the scene grid, NaN where no pixel applies.
// With bilinear, a pixel with data is one whose value is not NaN.
std::vector<float> geocode_slant_image(const Scene& scene, const Track& track,
                                       const SlarImage& image, std::span<const float> slant_values,
                                       GeocodeResampling resampling = GeocodeResampling::nearest);

// The same for 8-bit greytones; cells without a pixel get `fill` (0).
// With bilinear, a pixel with data is one without the no-data bit in
// image.mask, and the interpolated greytone is rounded to the nearest.
std::vector<std::uint8_t> geocode_slant_grey(
    const Scene& scene, const Track& track, const SlarImage& image,
    std::span<const std::uint8_t> slant_grey, std::uint8_t fill = 0,
    GeocodeResampling resampling = GeocodeResampling::nearest);

}  // namespace ris
