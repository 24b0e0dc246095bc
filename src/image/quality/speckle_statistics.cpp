#include "ris/image/speckle_statistics.h"

#include <algorithm>
#include <cmath>

#include "ris/util/error.h"

namespace ris {

namespace {

PixelBox clip(const IntensityView& img, const PixelBox& b) {
  PixelBox c;
  c.col0 = std::clamp(b.col0, 0, img.cols);
  c.row0 = std::clamp(b.row0, 0, img.rows);
  c.cols = std::clamp(b.col0 + b.cols, 0, img.cols) - c.col0;
  c.rows = std::clamp(b.row0 + b.rows, 0, img.rows) - c.row0;
  return c;
}

double median_of(std::vector<double> v) {
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(mid), v.end());
  return v[mid];
}

}  // namespace

RegionStatistics region_statistics(const IntensityView& img, const PixelBox& box) {
  RegionStatistics s;
  s.box = clip(img, box);
  double sum = 0.0, sum2 = 0.0;
  // Shifted by the first usable value: a one-pass variance without the
  // cancellation of sum2 - n mean^2 on bright regions.
  double shift = 0.0;
  bool have_shift = false;
  for (int r = s.box.row0; r < s.box.row0 + s.box.rows; ++r) {
    for (int c = s.box.col0; c < s.box.col0 + s.box.cols; ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * static_cast<std::size_t>(img.cols) +
                            static_cast<std::size_t>(c);
      if (!img.usable(i)) continue;
      const double v = img.intensity[i];
      if (!have_shift) shift = v, have_shift = true;
      sum += v - shift;
      sum2 += (v - shift) * (v - shift);
      ++s.pixels;
    }
  }
  if (s.pixels > 0) {
    const double n = double(s.pixels);
    s.mean = shift + sum / n;
    if (s.pixels > 1) s.std = std::sqrt(std::max(0.0, (sum2 - sum * sum / n) / (n - 1.0)));
  }
  return s;
}

std::vector<PixelBox> homogeneous_windows(const IntensityView& img, const HomogeneousRule& rule) {
  RIS_CHECK(rule.window >= 2);
  const int w = rule.window;
  std::vector<PixelBox> tiles;
  std::vector<double> cvs;
  for (int r = 0; r + w <= img.rows; r += w) {
    for (int c = 0; c + w <= img.cols; c += w) {
      const PixelBox b{c, r, w, w};
      const RegionStatistics s = region_statistics(img, b);
      if (double(s.pixels) < 0.9 * w * w || !(s.mean > 0.0)) continue;
      tiles.push_back(b);
      cvs.push_back(s.cv());
    }
  }
  if (tiles.empty()) return {};
  const double med = median_of(cvs);
  std::vector<double> dev(cvs.size());
  for (std::size_t i = 0; i < cvs.size(); ++i) dev[i] = std::abs(cvs[i] - med);
  const double limit = med + rule.mad_factor * 1.4826 * median_of(dev);
  std::vector<PixelBox> out;
  for (std::size_t i = 0; i < tiles.size(); ++i)
    if (cvs[i] <= limit) out.push_back(tiles[i]);
  return out;
}

SpeckleSummary pooled_speckle(const IntensityView& img, const std::vector<PixelBox>& boxes) {
  SpeckleSummary out;
  double ss = 0.0, dof = 0.0;
  for (const PixelBox& box : boxes) {
    const RegionStatistics s = region_statistics(img, box);
    if (s.pixels < 2 || !(s.mean > 0.0)) continue;
    // sum (I / m - 1)^2 = (n - 1) var / m^2.
    ss += double(s.pixels - 1) * (s.std * s.std) / (s.mean * s.mean);
    dof += double(s.pixels - 1);
    out.pixels += s.pixels;
    ++out.regions;
  }
  if (out.regions == 0 || !(ss > 0.0)) {
    throw InputError("image", "regions",
                     "no region has two or more pixels with data and a non-zero spread: the "
                     "speckle statistics need homogeneous regions of varying intensity");
  }
  const double var = ss / dof;
  out.enl = 1.0 / var;
  out.cv = std::sqrt(var);
  out.radiometric_resolution_db = radiometric_resolution_db(out.enl);
  return out;
}

double radiometric_resolution_db(double enl) {
  return 10.0 * std::log10(1.0 + 1.0 / std::sqrt(enl));
}

}  // namespace ris
