#include "ris/image/ground_range.h"

#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace ris
