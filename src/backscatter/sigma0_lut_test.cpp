#include "ris/backscatter/sigma0_lut.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ris/util/error.h"

namespace ris {
namespace {

// Lambert-like test source: sigma0 = g cos^2(theta) with g = 0.1 * (c + 1).
class CosSquaredSource : public Sigma0Source {
 public:
  bool has_category(std::uint16_t c) const override { return c < 5; }
  double sigma0(std::uint16_t c, double theta, const RadarBand&) const override {
    return 0.1 * (c + 1) * std::cos(theta) * std::cos(theta);
  }
  std::string category_name(std::uint16_t c) const override { return std::to_string(c); }
  std::string description() const override { return "cos^2 test source"; }
};

TEST(Sigma0Lut, InterpolatesWithin1e4Relative) {
  CosSquaredSource src;
  const std::uint16_t cats[] = {0, 3, 3};
  Sigma0Lut lut = Sigma0Lut::build(src, RadarBand{8.6e9, Polarisation::HH}, cats, "test");
  EXPECT_TRUE(lut.has(0));
  EXPECT_FALSE(lut.has(1));
  EXPECT_TRUE(lut.has(3));
  for (double deg = 0.0; deg < 89.0; deg += 0.37) {
    const double theta = deg_to_rad(deg);
    const double expected = 0.4 * std::cos(theta) * std::cos(theta);
    EXPECT_NEAR(lut.at(3, static_cast<float>(theta)), expected, 1e-4 * expected + 1e-7) << deg;
  }
}

TEST(Sigma0Lut, MissingCategoryIsAnInputError) {
  CosSquaredSource src;
  const std::uint16_t cats[] = {0, 7};
  EXPECT_THROW(Sigma0Lut::build(src, RadarBand{}, cats, "lib.toml"), InputError);
}

}  // namespace
}  // namespace ris
