#include "ris/image/geocode.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ris/util/error.h"

namespace ris {

GeocodeResampling parse_geocode_resampling(const std::string& text, const std::string& source,
                                           const std::string& key) {
  if (text == "near") return GeocodeResampling::nearest;
  if (text == "bilinear") return GeocodeResampling::bilinear;
  throw InputError(source, key,
                   "unknown geocoding resampling '" + text +
                       "': expected near (the default: each cell takes the pixel it falls in) "
                       "or bilinear (as gdalwarp -r)");
}

bool geocode_position(const Scene& scene, const Track& track, const SlarImage& img, int r, int c,
                      float elevation_m, double& line_out, double& bin_out) {
  const auto [x, y] = scene.cell_centre(r, c);
  const auto [s, u] = track.along_cross(x, y);
  if (!(u > 0.0)) return false;
  const double dz = track.altitude_m - elevation_m;
  line_out = s / img.line_spacing_m;
  bin_out = (std::sqrt(u * u + dz * dz) - img.range.near_m) / img.range.bin_m;
  return true;
}

bool geocode_pixel(const Scene& scene, const Track& track, const SlarImage& img, int r, int c,
                   float elevation_m, int& line_out, int& bin_out) {
  double l = 0.0, b = 0.0;
  if (!geocode_position(scene, track, img, r, c, elevation_m, l, b)) return false;
  const double line = std::floor(l);
  const double bin = std::floor(b);
  if (!(line >= 0 && line < img.lines && bin >= 0 && bin < img.bins)) return false;
  line_out = static_cast<int>(line);
  bin_out = static_cast<int>(bin);
  return true;
}

namespace {

// Bilinear between the four pixel centres around (line, bin), clamped at
// the image's edges, over the pixels `has_data` accepts; NaN when none.
template <typename T, typename HasData>
double bilinear_at(const SlarImage& img, std::span<const T> slant, double line, double bin,
                   HasData has_data) {
  const double l = line - 0.5, b = bin - 0.5;
  const double l0 = std::floor(l), b0 = std::floor(b);
  const double fl = l - l0, fb = b - b0;
  double sum = 0.0, weight = 0.0;
  for (int dl = 0; dl < 2; ++dl) {
    for (int db = 0; db < 2; ++db) {
      const double w = (dl ? fl : 1.0 - fl) * (db ? fb : 1.0 - fb);
      const int li = std::clamp(static_cast<int>(l0) + dl, 0, img.lines - 1);
      const int bi = std::clamp(static_cast<int>(b0) + db, 0, img.bins - 1);
      const std::size_t i = img.index(li, bi);
      if (w <= 0.0 || !has_data(i)) continue;
      sum += w * double(slant[i]);
      weight += w;
    }
  }
  return weight > 0.0 ? sum / weight : std::numeric_limits<double>::quiet_NaN();
}

// Each scene cell takes the value of the pixel it maps to (or the bilinear
// value around its position), else `fill`.
template <typename T, typename HasData, typename FromDouble>
std::vector<T> geocode(const Scene& scene, const Track& track, const SlarImage& img,
                       std::span<const T> slant, T fill, GeocodeResampling resampling,
                       HasData has_data, FromDouble from_double) {
  RIS_CHECK(slant.size() == static_cast<std::size_t>(img.lines) * img.bins);
  RIS_CHECK(img.line_spacing_m > 0.0 && img.range.bin_m > 0.0);
  std::vector<T> out(scene.size(), fill);
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      const std::size_t cell = scene.index(r, c);
      int line = 0, bin = 0;
      if (!(scene.valid[cell] &&
            geocode_pixel(scene, track, img, r, c, scene.elevation_m[cell], line, bin))) {
        continue;
      }
      if (resampling == GeocodeResampling::nearest) {
        out[cell] = slant[img.index(line, bin)];
        continue;
      }
      double l = 0.0, b = 0.0;
      geocode_position(scene, track, img, r, c, scene.elevation_m[cell], l, b);
      const double v = bilinear_at(img, slant, l, b, has_data);
      if (!std::isnan(v)) out[cell] = from_double(v);
    }
  }
  return out;
}

}  // namespace

std::vector<float> geocode_slant_image(const Scene& scene, const Track& track,
                                       const SlarImage& image, std::span<const float> slant_values,
                                       GeocodeResampling resampling) {
  return geocode(
      scene, track, image, slant_values, std::numeric_limits<float>::quiet_NaN(), resampling,
      [&](std::size_t i) { return !std::isnan(slant_values[i]); },
      [](double v) { return static_cast<float>(v); });
}

std::vector<std::uint8_t> geocode_slant_grey(const Scene& scene, const Track& track,
                                             const SlarImage& image,
                                             std::span<const std::uint8_t> slant_grey,
                                             std::uint8_t fill, GeocodeResampling resampling) {
  RIS_CHECK(resampling == GeocodeResampling::nearest || image.mask.size() == slant_grey.size());
  return geocode(
      scene, track, image, slant_grey, fill, resampling,
      [&](std::size_t i) { return !(image.mask[i] & pixel_flag::kNoData); },
      [](double v) { return static_cast<std::uint8_t>(std::clamp(std::lround(v), 0L, 255L)); });
}

}  // namespace ris
