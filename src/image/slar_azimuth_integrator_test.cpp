#include "ris/image/slar_azimuth_integrator.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <vector>

#include "ris/image/slar_image.h"

namespace ris {
namespace {

// integrate_slar_azimuth against its rule written out pixel by pixel from
// whole-image running sums, bit for bit, for SLAR footprints (window_lines
// 0) and constant windows, with 1, 2 and 3 threads (integrate_slar_azimuth
// gives each thread a range of bins).
void expect_the_per_pixel_rule(const SlarLineProfiles& prof,
                               std::initializer_list<double> windows_lines) {
  const int lines = prof.lines, bins = prof.bins;
  const int saved = omp_get_max_threads();
  for (const double window_lines : windows_lines) {
    SlarImagingParams p;
    p.range = SlantRangeBins{1000.0, 250.0, bins};  // the footprint grows 34x across the swath
    p.azimuth_beamwidth_rad = 0.02;
    p.azimuth_window_lines = window_lines;
    const double spacing_m = 20.0;
    // Whole-image running sums, in line order.
    const auto sums = [&](auto value) {
      std::vector<double> c(static_cast<std::size_t>(lines + 1) * bins, 0.0);
      for (int j = 0; j < lines; ++j)
        for (int b = 0; b < bins; ++b)
          c[static_cast<std::size_t>(j + 1) * bins + b] =
              c[static_cast<std::size_t>(j) * bins + b] + value(prof.index(j, b));
      return c;
    };
    const auto cum = sums([&](std::size_t i) { return double(prof.power_w[i]); });
    const auto cum_area = sums([&](std::size_t i) { return double(prof.area_m2[i]); });
    const auto bit_sum = [&](std::uint8_t bit) {
      return sums([&](std::size_t i) { return (prof.touch[i] & bit) ? 1.0 : 0.0; });
    };
    const auto cum_data = bit_sum(slar_touch::kData), cum_visible = bit_sum(slar_touch::kVisible),
               cum_layover = bit_sum(slar_touch::kLayover);
    for (const int threads : {1, 2, 3}) {  // each thread a range of bins
      omp_set_num_threads(threads);
      SlarImage img;
      img.lines = lines;
      img.bins = bins;
      img.range = p.range;
      integrate_slar_azimuth(prof, p, spacing_m, img);
      for (int k = 0; k < lines; ++k) {
        for (int b = 0; b < bins; ++b) {
          const double half =
              window_lines > 0.0
                  ? 0.5 * window_lines
                  : 0.5 * slar_footprint_m(p.range.centre_m(b), p.azimuth_beamwidth_rad) /
                        spacing_m;
          const auto integral = [&](const std::vector<double>& c, double x) {
            const double y = std::clamp(x + 0.5, 0.0, double(lines));
            const int i = std::min(static_cast<int>(y), lines - 1);
            const double f = y - i;
            const double c0 = c[static_cast<std::size_t>(i) * bins + b];
            const double c1 = c[static_cast<std::size_t>(i + 1) * bins + b];
            return c0 + f * (c1 - c0);
          };
          const double a = k - half, e = k + half;
          const float power = static_cast<float>(integral(cum, e) - integral(cum, a));
          const float area = static_cast<float>(integral(cum_area, e) - integral(cum_area, a));
          const int j_lo = std::max(0, static_cast<int>(std::floor(a - 0.5)) + 1);
          const int j_hi = std::min(lines - 1, static_cast<int>(std::ceil(e + 0.5)) - 1);
          const auto count = [&](const std::vector<double>& c) {
            return c[static_cast<std::size_t>(j_hi + 1) * bins + b] -
                   c[static_cast<std::size_t>(j_lo) * bins + b];
          };
          std::uint8_t m = 0;
          if (count(cum_data) == 0) m |= pixel_flag::kNoData;
          if (count(cum_data) > 0 && count(cum_visible) == 0) m |= pixel_flag::kShadow;
          if (count(cum_layover) > 0) m |= pixel_flag::kLayover;
          const std::size_t at = img.index(k, b);
          ASSERT_EQ(std::memcmp(&img.mean_power_w[at], &power, sizeof power), 0)
              << k << " " << b << " window " << window_lines << " threads " << threads;
          ASSERT_EQ(std::memcmp(&img.area_m2[at], &area, sizeof area), 0) << k << " " << b;
          ASSERT_EQ(img.mask[at], m) << k << " " << b;
        }
      }
    }
  }
  omp_set_num_threads(saved);
}

// The azimuth step (vectorised four bins at a time where the running-sum rows
// agree) against its rule: a footprint that grows fast across the swath
// (blocks of four bins whose rows differ), a constant SAR window, zero-power
// and no-data lines, bins % 4 != 0.
TEST(SlarAzimuthIntegrator, EqualsThePerPixelRuleFromWholeImageSums) {
  const int lines = 301, bins = 150;
  SlarLineProfiles prof;
  prof.allocate(lines, bins);
  for (int l = 0; l < lines; ++l) {
    for (int b = 0; b < bins; ++b) {
      const std::size_t i = prof.index(l, b);
      const bool none = (l / 7 + b) % 11 == 0;
      prof.power_w[i] = none ? 0.0f : static_cast<float>(1e-9 * (1.5 + std::sin(0.37 * double(i))));
      prof.area_m2[i] = none ? 0.0f : static_cast<float>(40.0 + 3.0 * std::cos(0.11 * double(i)));
      prof.touch[i] = none ? 0
                           : static_cast<std::uint8_t>(slar_touch::kData |
                                                       ((i % 5 != 0) ? slar_touch::kVisible : 0) |
                                                       ((i % 13 == 0) ? slar_touch::kLayover : 0));
    }
  }
  expect_the_per_pixel_rule(prof, {0.0, 6.5});
}

// emit() writes the no-data pixel directly outside the union of the lines'
// data extents over a footprint: the same bytes as the rule, with an
// oblique track's wedges of empty bins (extents that grow and shrink by
// more than a footprint per line), whole empty lines, a lone bin of power
// without touch bits (a SAR range window's spill), area alone, touch alone,
// and -0 W (a zero of either sign adds nothing).
TEST(SlarAzimuthIntegrator, SkipsNoDataBinsWithTheRulesBytes) {
  const int lines = 203, bins = 150;
  SlarLineProfiles prof;
  prof.allocate(lines, bins);
  for (int l = 0; l < lines; ++l) {
    const int lo = std::abs(l - 100) * 3 / 2 - 20, hi = 160 - std::abs(l - 90) * 2;
    for (int b = 0; b < bins; ++b) {
      const std::size_t i = prof.index(l, b);
      const bool data = b >= lo && b < hi && l % 37 != 5;
      prof.power_w[i] = data ? static_cast<float>(1e-9 * (1.5 + std::sin(0.37 * double(i)))) : 0.0f;
      prof.area_m2[i] = data ? static_cast<float>(40.0 + 3.0 * std::cos(0.11 * double(i))) : 0.0f;
      prof.touch[i] = data ? static_cast<std::uint8_t>(slar_touch::kData |
                                                       ((i % 5 != 0) ? slar_touch::kVisible : 0))
                           : 0;
    }
  }
  prof.power_w[prof.index(3, 140)] = 2e-9f;             // power alone, far from any data
  prof.area_m2[prof.index(150, 2)] = 5.0f;              // area alone
  prof.touch[prof.index(20, 147)] = slar_touch::kData;  // touch alone, the last quad
  prof.power_w[prof.index(60, 1)] = -0.0f;
  prof.power_w[prof.index(61, 149)] = -0.0f;
  expect_the_per_pixel_rule(prof, {0.0, 6.5, 31.0});
}

}  // namespace
}  // namespace ris
