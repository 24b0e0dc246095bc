#include "ris/image/slar_azimuth_integrator.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "ris/image/slar_image.h"

namespace ris {
namespace {

// The azimuth step (vectorised four bins at a time where the running-sum rows
// agree) against its rule written out pixel by pixel from whole-image running
// sums, bit for bit: a footprint that grows fast across the swath (blocks of
// four bins whose rows differ), a constant SAR window, zero-power and
// no-data lines, bins % 4 != 0, 1, 2 and 3 threads (integrate_slar_azimuth
// gives each thread a range of bins).
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
  const int saved = omp_get_max_threads();
  for (const double window_lines : {0.0, 6.5}) {
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

}  // namespace
}  // namespace ris
