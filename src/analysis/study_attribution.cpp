// Which slant-range pixels of a study compare categories at matched geometry
// (ris/analysis/study_separability.h, points 2; ris/analysis/study.h for which
// elements contribute to a pixel).
#include <algorithm>
#include <cmath>
#include <limits>

#include "ris/analysis/study.h"
#include "ris/analysis/study_separability.h"
#include "ris/image/slar_image.h"
#include "ris/util/error.h"

namespace ris {

namespace {

constexpr std::int32_t kEmpty = -1;
constexpr std::int32_t kMixed = -2;

// What reaches one (line, bin): one category or none or several, and the
// span of the contributors' local incidence.
struct Cell {
  std::int32_t category = kEmpty;
  float lo = std::numeric_limits<float>::infinity();
  float hi = -std::numeric_limits<float>::infinity();
  void merge(std::int32_t c, float lo_rad, float hi_rad) {
    if (category == kEmpty) {
      category = c;
    } else if (category != c) {
      category = kMixed;
    }
    lo = std::min(lo, lo_rad);
    hi = std::max(hi, hi_rad);
  }
};

// The cells reached from each line's own elements, over the range bins each
// element's slant-range span overlaps (slar_image.h).
std::vector<Cell> own_line_cells(const SlarGeometry& g, const SlarImage& img) {
  std::vector<Cell> own(static_cast<std::size_t>(img.lines) * static_cast<std::size_t>(img.bins));
  for (int l = 0; l < g.lines; ++l) {
    for (int s = 0; s < g.samples; ++s) {
      const std::size_t i = g.index(l, s);
      if (!sample_visible(g.flags[i])) continue;
      const double r = g.slant_range_m[i];
      const double a = g.range_near_end_m[i];
      const double b = g.range_far_end_m[i];
      if (!std::isfinite(r)) continue;
      double r0 = r, r1 = r;
      if (std::isfinite(a)) r0 = std::min(r0, a), r1 = std::max(r1, a);
      if (std::isfinite(b)) r0 = std::min(r0, b), r1 = std::max(r1, b);
      const double k0f = std::floor((r0 - img.range.near_m) / img.range.bin_m);
      const double k1f = std::floor((r1 - img.range.near_m) / img.range.bin_m);
      if (k1f < 0.0 || k0f >= img.bins) continue;
      const int k0 = static_cast<int>(std::max(k0f, 0.0));
      const int k1 = static_cast<int>(std::min(k1f, double(img.bins - 1)));
      const float t = g.local_incidence_rad[i];
      for (int k = k0; k <= k1; ++k) own[img.index(l, k)].merge(g.category[i], t, t);
    }
  }
  return own;
}

}  // namespace

PixelAttribution attribute_pixels(const SlarSimulation& sim) {
  const SlarGeometry& g = sim.geometry;
  // Needs the per-sample geometry: simulate_slar with SlarOptions::keep_geometry.
  RIS_CHECK(g.flags.size() ==
            static_cast<std::size_t>(g.lines) * static_cast<std::size_t>(g.samples));
  const SlarImage& img = sim.image;
  RIS_CHECK(g.lines == img.lines);
  const std::vector<Cell> own = own_line_cells(g, img);

  // Azimuth: the footprint w(R) = R phi gathers lines within w/2 (plus the
  // line strip's half width) of the pixel's line.
  const double phi = sim.radar.azimuth_beamwidth_rad;
  const double ds = img.line_spacing_m;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  PixelAttribution out;
  out.category.assign(own.size(), kEmpty);
  out.incidence_lo_rad.assign(own.size(), nan);
  out.incidence_hi_rad.assign(own.size(), nan);
  for (int k = 0; k < img.bins; ++k) {
    const double w = slar_footprint_m(img.range.centre_m(k), phi);
    const int h = static_cast<int>(std::ceil(0.5 * w / ds + 0.5));
    for (int l = 0; l < img.lines; ++l) {
      const std::size_t p = img.index(l, k);
      if ((img.mask[p] & (pixel_flag::kShadow | pixel_flag::kLayover | pixel_flag::kNoData)) != 0) {
        continue;
      }
      // The whole footprint must lie on imaged lines, and every line of it
      // must put elements of one category into this bin: a line with none
      // (shadow, beyond the scene or the track's ends) would lower the power.
      if (l - h < 0 || l + h >= img.lines) continue;
      Cell cell;
      for (int m = l - h; m <= l + h && cell.category != kMixed; ++m) {
        const Cell& o = own[img.index(m, k)];
        if (o.category < 0) {
          cell.category = kMixed;
          break;
        }
        cell.merge(o.category, o.lo, o.hi);
      }
      if (cell.category < 0) continue;
      out.category[p] = cell.category;
      out.incidence_lo_rad[p] = cell.lo;
      out.incidence_hi_rad[p] = cell.hi;
    }
  }
  return out;
}

std::vector<std::int32_t> pure_category_map(const SlarSimulation& sim) {
  return attribute_pixels(sim).category;
}

IncidenceBins incidence_bins(const SlarSimulation& sim, const PixelAttribution& at,
                             const StudyWindow& window) {
  RIS_CHECK(window.incidence_bin_rad > 0.0);
  RIS_CHECK(window.range_lo_fraction >= 0.0 && window.range_hi_fraction <= 1.0 &&
            window.range_lo_fraction < window.range_hi_fraction);
  const SlarImage& img = sim.image;
  IncidenceBins ib;
  ib.width_rad = window.incidence_bin_rad;
  const double extent = img.bins * img.range.bin_m;
  ib.range_lo_m = img.range.near_m + window.range_lo_fraction * extent;
  ib.range_hi_m = img.range.near_m + window.range_hi_fraction * extent;
  ib.bin.assign(at.category.size(), -1);
  ib.incidence_rad.assign(at.category.size(), std::numeric_limits<float>::quiet_NaN());
  // Bins from 0 rad: the same edges in every band and run.
  int lo_bin = std::numeric_limits<int>::max(), hi_bin = -1;
  std::vector<int> raw(at.category.size(), -1);
  for (int k = 0; k < img.bins; ++k) {
    const double r = img.range.centre_m(k);
    if (r < ib.range_lo_m || r > ib.range_hi_m) continue;
    for (int l = 0; l < img.lines; ++l) {
      const std::size_t p = img.index(l, k);
      if (at.category[p] < 0) continue;
      const int b0 = static_cast<int>(std::floor(at.incidence_lo_rad[p] / ib.width_rad));
      const int b1 = static_cast<int>(std::floor(at.incidence_hi_rad[p] / ib.width_rad));
      if (b0 != b1) continue;  // contributors straddle a bin edge: not matched
      raw[p] = b0;
      lo_bin = std::min(lo_bin, b0);
      hi_bin = std::max(hi_bin, b0);
    }
  }
  if (hi_bin < 0) return ib;
  ib.count = hi_bin - lo_bin + 1;
  ib.first_lo_rad = lo_bin * ib.width_rad;
  for (std::size_t p = 0; p < raw.size(); ++p) {
    if (raw[p] < 0) continue;
    ib.bin[p] = raw[p] - lo_bin;
    ib.incidence_rad[p] = 0.5f * (at.incidence_lo_rad[p] + at.incidence_hi_rad[p]);
  }
  return ib;
}

}  // namespace ris
