#include "ris/image/geocode.h"

#include <cmath>
#include <limits>

#include "ris/util/error.h"

namespace ris {

namespace {

// Each scene cell takes the value of the pixel it maps to, else `fill`.
template <typename T, typename Fill>
std::vector<T> geocode(const Scene& scene, const Track& track, const SlarImage& img,
                       const std::vector<T>& slant, Fill fill) {
  RIS_CHECK(slant.size() == static_cast<std::size_t>(img.lines) * img.bins);
  RIS_CHECK(img.line_spacing_m > 0.0 && img.range.bin_m > 0.0);
  std::vector<T> out(scene.size(), fill);
  const double h_sensor = track.altitude_m;
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      const std::size_t cell = scene.index(r, c);
      if (!scene.valid[cell]) continue;
      const auto [x, y] = scene.cell_centre(r, c);
      const auto [s, u] = track.along_cross(x, y);
      if (!(u > 0.0)) continue;
      const double line = std::floor(s / img.line_spacing_m);
      const double dz = h_sensor - scene.elevation_m[cell];
      const double bin =
          std::floor((std::sqrt(u * u + dz * dz) - img.range.near_m) / img.range.bin_m);
      if (!(line >= 0 && line < img.lines && bin >= 0 && bin < img.bins)) continue;
      out[cell] = slant[img.index(static_cast<int>(line), static_cast<int>(bin))];
    }
  }
  return out;
}

}  // namespace

std::vector<float> geocode_slant_image(const Scene& scene, const Track& track,
                                       const SlarImage& image,
                                       const std::vector<float>& slant_values) {
  return geocode(scene, track, image, slant_values, std::numeric_limits<float>::quiet_NaN());
}

std::vector<std::uint8_t> geocode_slant_grey(const Scene& scene, const Track& track,
                                             const SlarImage& image,
                                             const std::vector<std::uint8_t>& slant_grey,
                                             std::uint8_t fill) {
  return geocode(scene, track, image, slant_grey, fill);
}

}  // namespace ris
