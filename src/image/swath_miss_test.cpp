#include "ris/image/swath_miss.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "ris/util/error.h"

namespace ris {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

InputError error_of(double r_min_m, double r_max_m) {
  try {
    throw_swath_misses_scene("radar.toml", SlantRangeBins{5000.0, 15.0, 100}, r_min_m, r_max_m,
                             "track");
  } catch (const InputError& e) {
    return e;
  }
  return InputError("", "", "not thrown");
}

TEST(SwathMiss, ASceneInViewBlamesTheSweepDelayWithBothExtents) {
  const InputError e = error_of(7000.0, 8000.0);
  EXPECT_EQ(e.key(), "sweep_delay");
  EXPECT_THAT(e.what(), HasSubstr("the swath (slant range 5000.0 to 6500.0 m) misses the scene, "
                                  "which spans slant range 7000.0 to 8000.0 m"));
}

TEST(SwathMiss, NothingInViewNamesThePlacingKeysAndNoInfinity) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const InputError e = error_of(kInf, -kInf);
  EXPECT_EQ(e.key(), "track");
  EXPECT_THAT(e.what(), HasSubstr("no cell of the scene with data is in view of the radar"));
  EXPECT_THAT(e.what(), Not(HasSubstr("inf")));
  EXPECT_THAT(e.what(), Not(HasSubstr("sweep_delay")));
}

}  // namespace
}  // namespace ris
