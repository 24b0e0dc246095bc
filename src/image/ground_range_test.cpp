#include "ris/image/ground_range.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>
#include <vector>

#include "ris/util/error.h"

namespace ris {
namespace {

TEST(GroundRange, GridSpansTheSwathOverTheReferenceHeight) {
  const SlantRangeBins bins{5000.0, 15.0, 100};
  const GroundRangeGrid g = ground_range_grid(bins, 3000.0, 100.0, 6.0);
  EXPECT_NEAR(g.near_m, std::sqrt(5000.0 * 5000.0 - 2900.0 * 2900.0), 1e-9);
  const double far = std::sqrt(6500.0 * 6500.0 - 2900.0 * 2900.0);
  EXPECT_EQ(g.count, static_cast<int>(std::ceil((far - g.near_m) / 6.0)));
  EXPECT_THROW(ground_range_grid(bins, 3000.0, 3000.0, 6.0), InputError);
}

TEST(GroundRange, ResamplesLinearlyInSlantRange) {
  // A raster whose value is its bin index: the resampled value is the ground
  // pixel's fractional bin coordinate.
  const SlantRangeBins bins{5000.0, 15.0, 100};
  std::vector<float> slant(2 * 100);
  for (int line = 0; line < 2; ++line)
    for (int k = 0; k < 100; ++k) slant[static_cast<std::size_t>(line * 100 + k)] = float(k);
  const GroundRangeGrid g = ground_range_grid(bins, 3000.0, 0.0, 6.0);
  const std::vector<float> ground = to_ground_range(slant, 2, bins, g);
  ASSERT_EQ(ground.size(), static_cast<std::size_t>(2 * g.count));
  for (int j = 0; j < g.count; ++j) {
    const double x = (std::hypot(g.centre_m(j), 3000.0) - 5000.0) / 15.0 - 0.5;
    const float got = ground[static_cast<std::size_t>(g.count + j)];
    if (x > 99.5) {  // the last pixel may reach past the far range
      EXPECT_EQ(j, g.count - 1);
      EXPECT_TRUE(std::isnan(got));
      continue;
    }
    EXPECT_NEAR(got, std::clamp(x, 0.0, 99.0), 1e-4) << j;
  }
  // Masks take the nearest bin.
  std::vector<std::uint8_t> mask(200, 0);
  mask[150] = 4;  // line 1, bin 50
  const std::vector<std::uint8_t> gm = to_ground_range_nearest(mask, 2, bins, g, 255);
  int hits = 0;
  for (int j = 0; j < g.count; ++j) {
    const double x = (std::hypot(g.centre_m(j), 3000.0) - 5000.0) / 15.0 - 0.5;
    const bool in50 = std::round(x) == 50.0;
    const int expected = std::round(x) >= 100.0 ? 255 : (in50 ? 4 : 0);
    EXPECT_EQ(gm[static_cast<std::size_t>(g.count + j)], expected) << j;
    hits += in50 ? 1 : 0;
  }
  EXPECT_GT(hits, 1);  // ~ dr / sin(theta) / du ground pixels per bin
}

// The per-line kernels (vectorised where the CPU allows) against the
// documented per-pixel rule, bit for bit: a grid reaching past the swath at
// both ends, NaN and random bins, widths that leave vector tails; ground
// pixels smaller than a bin (the vector kernels' blocks read a few bins) and
// larger (their blocks fall back to the scalar loop), and mixed.
TEST(GroundRange, LineKernelsEqualThePerPixelRule) {
  for (const double spacing_m : {3.7, 11.0, 40.0})
    for (const int count : {1, 2, 5, 37, 301}) {
      const SlantRangeBins bins{5000.0, 15.0, count};
      GroundRangeGrid g = ground_range_grid(bins, 3000.0, 40.0, spacing_m);
      g.near_m -= 50.0;  // starts before the near range
      g.count += 40;     // ends past the far range
      const double D = g.altitude_m - g.reference_height_m;
      const int lines = 3;
      std::vector<float> slant(static_cast<std::size_t>(lines * count));
      std::vector<std::uint8_t> mask(slant.size());
      for (std::size_t i = 0; i < slant.size(); ++i) {
        slant[i] = (i % 13 == 4) ? std::numeric_limits<float>::quiet_NaN()
                                 : static_cast<float>(std::sin(double(i) * 1.7) * 1e-3 + 2e-3);
        mask[i] = static_cast<std::uint8_t>((i * 7) % 251);
      }
      const std::vector<float> ground = to_ground_range(slant, lines, bins, g);
      const std::vector<std::uint8_t> gm = to_ground_range_nearest(mask, lines, bins, g, 255);
      const int last = count - 1;
      for (int line = 0; line < lines; ++line) {
        const float* row = slant.data() + line * count;
        for (int j = 0; j < g.count; ++j) {
          const std::size_t at = static_cast<std::size_t>(line * g.count + j);
          const double x = (std::hypot(g.centre_m(j), D) - bins.near_m) / bins.bin_m - 0.5;
          float want = std::numeric_limits<float>::quiet_NaN();
          if (!(x < -0.5 || x > last + 0.5)) {
            const double xc = std::clamp(x, 0.0, double(last));
            const int k = std::min(static_cast<int>(xc), std::max(last - 1, 0));
            const double f = xc - k;
            const float a = row[k], b = row[std::min(k + 1, last)];
            want = static_cast<float>(a + f * (double(b) - double(a)));
          }
          const float got = ground[at];
          if (std::isnan(want)) {
            EXPECT_TRUE(std::isnan(got)) << count << " " << j;
          } else {
            EXPECT_EQ(std::memcmp(&got, &want, sizeof got), 0) << count << " " << j;
          }
          const double r = std::round(x);
          const int near = (r >= 0.0 && r < count) ? static_cast<int>(r) : -1;
          EXPECT_EQ(gm[at], near >= 0 ? mask[static_cast<std::size_t>(line * count + near)] : 255)
              << count << " " << j;
        }
      }
    }
}

// columns_within and the restricted resample_line (the render's skip of a
// line's no-data ends): with the bins outside [first, end) NaN, the same
// bytes as the whole line's resample; every column outside the run is NaN.
TEST(GroundRange, ColumnsWithinABinRangeResampleAsTheWholeLine) {
  const int count = 301;
  const SlantRangeBins bins{5000.0, 15.0, count};
  for (const double spacing_m : {3.7, 40.0}) {
    GroundRangeGrid g = ground_range_grid(bins, 3000.0, 40.0, spacing_m);
    g.near_m -= 50.0;
    g.count += 40;
    const GroundRangeResampler resampler(bins, g);
    const auto cols = static_cast<std::size_t>(resampler.columns());
    for (const auto& [first, end] : {std::pair{0, count}, std::pair{17, 260}, std::pair{150, 151},
                                     std::pair{0, 1}, std::pair{300, 301}, std::pair{90, 90}}) {
      std::vector<float> row(static_cast<std::size_t>(count),
                             std::numeric_limits<float>::quiet_NaN());
      for (int k = first; k < end; ++k)
        row[static_cast<std::size_t>(k)] = static_cast<float>(1e-3 + 1e-4 * std::sin(k * 0.9));
      std::vector<float> whole(cols), part(cols, 7.0f);
      resampler.resample_line(row.data(), whole.data());
      const GroundRangeResampler::Columns run = resampler.columns_within(first, end);
      ASSERT_LE(run.begin, run.end);
      ASSERT_LE(run.end, cols);
      resampler.resample_line(row.data(), part.data(), run);
      std::size_t numbers = 0;
      for (std::size_t j = 0; j < cols; ++j) {
        EXPECT_EQ(std::isnan(whole[j]), std::isnan(part[j])) << first << " " << j;
        if (!std::isnan(whole[j])) {
          EXPECT_EQ(std::memcmp(&whole[j], &part[j], sizeof(float)), 0) << first << " " << j;
          EXPECT_TRUE(j >= run.begin && j < run.end) << first << " " << j;
          ++numbers;
        }
      }
      if (end - first >= 2) {
        EXPECT_GT(numbers, 0u) << first << " " << end;
      }
    }
  }
}

}  // namespace
}  // namespace ris
