#include "ris/image/geocode.h"

#include <cmath>
#include <limits>

#include "ris/util/error.h"

namespace ris {

bool geocode_pixel(const Scene& scene, const Track& track, const SlarImage& img, int r, int c,
                   float elevation_m, int& line_out, int& bin_out) {
  const auto [x, y] = scene.cell_centre(r, c);
  const auto [s, u] = track.along_cross(x, y);
  if (!(u > 0.0)) return false;
  const double line = std::floor(s / img.line_spacing_m);
  const double dz = track.altitude_m - elevation_m;
  const double bin = std::floor((std::sqrt(u * u + dz * dz) - img.range.near_m) / img.range.bin_m);
  if (!(line >= 0 && line < img.lines && bin >= 0 && bin < img.bins)) return false;
  line_out = static_cast<int>(line);
  bin_out = static_cast<int>(bin);
  return true;
}

namespace {

// Each scene cell takes the value of the pixel it maps to, else `fill`.
template <typename T, typename Fill>
std::vector<T> geocode(const Scene& scene, const Track& track, const SlarImage& img,
                       std::span<const T> slant, Fill fill) {
  RIS_CHECK(slant.size() == static_cast<std::size_t>(img.lines) * img.bins);
  RIS_CHECK(img.line_spacing_m > 0.0 && img.range.bin_m > 0.0);
  std::vector<T> out(scene.size(), fill);
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      const std::size_t cell = scene.index(r, c);
      int line = 0, bin = 0;
      if (scene.valid[cell] &&
          geocode_pixel(scene, track, img, r, c, scene.elevation_m[cell], line, bin)) {
        out[cell] = slant[img.index(line, bin)];
      }
    }
  }
  return out;
}

}  // namespace

std::vector<float> geocode_slant_image(const Scene& scene, const Track& track,
                                       const SlarImage& image,
                                       std::span<const float> slant_values) {
  return geocode(scene, track, image, slant_values, std::numeric_limits<float>::quiet_NaN());
}

std::vector<std::uint8_t> geocode_slant_grey(const Scene& scene, const Track& track,
                                             const SlarImage& image,
                                             std::span<const std::uint8_t> slant_grey,
                                             std::uint8_t fill) {
  return geocode(scene, track, image, slant_grey, fill);
}

}  // namespace ris
