#include "ris/image/ppi_scope.h"

#include <fmt/format.h>

#include <cmath>
#include <limits>

#include "ris/util/error.h"
#include "ris/util/resource_guard.h"
#include "ris/util/units.h"

namespace ris {

std::int64_t ppi_scope_source(const PpiScopeGrid& g, int row, int col) {
  const double e = g.east_m(col), n = g.north_m(row);
  const double r = std::hypot(e, n);
  const double R = g.presentation == PpiPresentation::slant ? r : std::hypot(r, g.depth_m);
  const double pos = (R - g.range.near_m) / g.range.bin_m;
  if (!(pos >= 0.0 && pos < g.range.count)) return -1;
  double a = std::atan2(e, n) - g.scan_start_rad;  // clockwise from the sector's start
  a -= 2.0 * kPi * std::floor(a / (2.0 * kPi));
  const double k = std::floor(a / g.ray_spacing_rad);
  if (!(k >= 0.0)) return -1;
  int ray = static_cast<int>(k);
  if (ray >= g.rays) {
    if (!g.full_circle) return -1;
    ray = g.rays - 1;  // rounding at 360 deg
  }
  return static_cast<std::int64_t>(ray) * g.range.count + static_cast<std::int64_t>(pos);
}

bool on_range_ring(const PpiScopeGrid& g, int row, int col, double spacing_m) {
  const double r = std::hypot(g.east_m(col), g.north_m(row));
  const double k = std::round(r / spacing_m);
  return k >= 1.0 && std::abs(r - k * spacing_m) <= 0.5 * g.pixel_m;
}

namespace {

template <typename T>
std::vector<T> convert(std::span<const T> bscope, const PpiScopeGrid& g, T fill) {
  RIS_CHECK(bscope.size() ==
            static_cast<std::size_t>(g.rays) * static_cast<std::size_t>(g.range.count));
  std::vector<T> out(static_cast<std::size_t>(g.size) * static_cast<std::size_t>(g.size), fill);
#pragma omp parallel for schedule(static)
  for (int row = 0; row < g.size; ++row) {
    for (int col = 0; col < g.size; ++col) {
      const std::int64_t i = ppi_scope_source(g, row, col);
      if (i >= 0) {
        out[static_cast<std::size_t>(row) * static_cast<std::size_t>(g.size) +
            static_cast<std::size_t>(col)] = bscope[static_cast<std::size_t>(i)];
      }
    }
  }
  return out;
}

}  // namespace

PpiScopeGrid ppi_scope_grid(const RadarParams& radar, const SlantRangeBins& range, int rays,
                            double depth_m) {
  PpiScopeGrid g;
  const PpiParams& p = radar.ppi;
  g.pixel_m = p.scope_pixel_m;
  g.presentation = p.presentation;
  g.depth_m = depth_m;
  g.scan_start_rad = p.scan_start_rad;
  g.ray_spacing_rad = p.ray_spacing_rad;
  g.rays = rays;
  g.full_circle = p.full_circle();
  g.range = range;
  const double far = range.far_m();
  const double radius = p.presentation == PpiPresentation::slant
                            ? far
                            : std::sqrt(std::max(0.0, far * far - depth_m * depth_m));
  // Checked before the cast and the allocation: a 1 mm pixel once ended in
  // std::bad_alloc. The scope holds power (4 bytes), mask and greytone (1
  // each) per pixel, plus copies while writing: 12 bytes a pixel.
  constexpr std::int64_t kMaxHalfSize = 1 << 20;  // a 2 M x 2 M pixel scope
  g.size = 2 * std::max(1, static_cast<int>(checked_count(std::ceil(radius / g.pixel_m),
                                                          kMaxHalfSize, radar.source_file,
                                                          "scan.pixel", "scope pixels a side")));
  require_memory(checked_mul(checked_mul(g.size, g.size, radar.source_file, "scan.pixel"), 12,
                             radar.source_file, "scan.pixel"),
                 radar.source_file, "scan.pixel",
                 fmt::format("a PPI scope of {} x {} pixels", g.size, g.size));
  return g;
}

std::vector<float> to_ppi_scope(std::span<const float> bscope, const PpiScopeGrid& grid) {
  return convert<float>(bscope, grid, std::numeric_limits<float>::quiet_NaN());
}

std::vector<std::uint8_t> to_ppi_scope_nearest(std::span<const std::uint8_t> bscope,
                                               const PpiScopeGrid& grid, std::uint8_t fill) {
  return convert<std::uint8_t>(bscope, grid, fill);
}

void draw_range_rings(std::span<std::uint8_t> grey, const PpiScopeGrid& g, double spacing_m,
                      std::uint8_t value) {
  RIS_CHECK(grey.size() == static_cast<std::size_t>(g.size) * static_cast<std::size_t>(g.size));
  if (!(spacing_m > 0.0)) return;
  for (int row = 0; row < g.size; ++row) {
    for (int col = 0; col < g.size; ++col) {
      if (on_range_ring(g, row, col, spacing_m)) {
        grey[static_cast<std::size_t>(row) * static_cast<std::size_t>(g.size) +
             static_cast<std::size_t>(col)] = value;
      }
    }
  }
}

}  // namespace ris
