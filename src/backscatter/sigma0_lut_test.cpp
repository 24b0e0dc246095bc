#include "ris/backscatter/sigma0_lut.h"
#include "build_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "ris/backscatter/library.h"
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

// The shipped libraries' models (Oh 1992 and water cloud over Mironov soil,
// small perturbation water, constant gamma, ...) against the table at 0.05
// deg: the interpolation error stays below 1e-3 relative between 1 and 85
// deg at L, X and Ku band, both like polarisations.
TEST(Sigma0Lut, ShippedLibrariesInterpolateWithin1e3Relative) {
  for (const char* file : {"ku-geometric.toml", "generic-terrain.toml"}) {
    const auto src =
        load_sigma0_source(std::string(ris::test::data_dir()) + "/backscatter/" + file);
    std::vector<std::uint16_t> cats;
    for (int c = 0; c < 100; ++c)
      if (src->has_category(static_cast<std::uint16_t>(c)))
        cats.push_back(static_cast<std::uint16_t>(c));
    ASSERT_FALSE(cats.empty()) << file;
    for (const double f_hz : {1.25e9, 8.6e9, 13.3e9}) {
      for (const Polarisation pol : {Polarisation::HH, Polarisation::VV}) {
        const RadarBand band{f_hz, pol};
        const Sigma0Lut lut = Sigma0Lut::build(*src, band, cats, file);
        double worst = 0.0;
        for (const std::uint16_t c : cats) {
          for (double deg = 1.0; deg <= 85.0; deg += 0.137) {
            const double theta = deg_to_rad(deg);
            const double direct = src->sigma0(c, theta, band);
            // The table is looked up with a float angle, as the simulation does.
            const double looked_up = lut.at(c, static_cast<float>(theta));
            if (direct > 0.0) worst = std::max(worst, std::abs(looked_up - direct) / direct);
          }
        }
        EXPECT_LT(worst, 1e-3) << file << " " << f_hz;
      }
    }
  }
}

TEST(Sigma0Lut, MissingCategoryIsAnInputError) {
  CosSquaredSource src;
  const std::uint16_t cats[] = {0, 7};
  EXPECT_THROW(Sigma0Lut::build(src, RadarBand{}, cats, "lib.toml"), InputError);
}

}  // namespace
}  // namespace ris
