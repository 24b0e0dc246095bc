#include "ris/geometry/swath_coverage.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "ris/util/units.h"

namespace ris {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// The small SLAR of tests/test_inputs.h: 3000 m up, 4000 m west of the
// scene's west edge, heading north; 33.4 us delay and 10 us sweep.
Track west_track(const Scene& s, double near_edge_m = 4000.0) {
  TrackSpec spec;
  spec.altitude_m = 3000.0;
  spec.near_edge_ground_m = near_edge_m;
  return resolve_track(spec, s, "radar.toml");
}

SlantRangeBins swath(double delay_s, double sweep_s) {
  // 0.1 us bins (c tau / 2), as the radar's.
  const double near_m = kSpeedOfLight_m_per_s * delay_s / 2.0;
  const double bin_m = kSpeedOfLight_m_per_s * 0.1e-6 / 2.0;
  return {near_m, bin_m, static_cast<int>(std::lround(sweep_s / 0.1e-6))};
}

TEST(SwathCoverage, ANearStripOfAWideSceneIsWarnedOfWithItsWidths) {
  // 5 km across (500 columns of 10 m): the swath's ground band is
  // sqrt(R^2 - H^2) for R = R_near .. R_far (MODEL.md section 2).
  const Scene s = Scene::flat(100, 500, 10.0, 0.0f, 1);
  const SlantRangeBins b = swath(33.4e-6, 10e-6);
  const double u_near = std::sqrt(b.near_m * b.near_m - 9e6);
  const double u_far = std::sqrt(b.far_m() * b.far_m() - 9e6);
  const SwathCoverage c = swath_coverage(west_track(s), s, b, 0.0);
  EXPECT_NEAR(c.across_scene_m, 5000.0, 1e-6);
  EXPECT_NEAR(c.across_imaged_m, u_far - u_near, 1e-6);
  EXPECT_NEAR(c.along_imaged_m, 1000.0, 1e-6);
  // Cell centres at u = 4005, 4015, ... m: those from u_near to u_far.
  const double in = std::floor((u_far - 4005.0) / 10.0) - std::ceil((u_near - 4005.0) / 10.0) + 1;
  EXPECT_NEAR(c.cell_fraction, in / 500.0, 1e-12);
  const auto w = swath_coverage_warning(c);
  ASSERT_TRUE(w.has_value());
  EXPECT_THAT(*w, HasSubstr("the swath images 1.8 km of the scene's 5.0 km across track (near "
                            "side): 35 % of its cells"));
  EXPECT_THAT(*w, HasSubstr("widen sweep_length or move the track"));
  EXPECT_THAT(*w, Not(HasSubstr("along track")));
}

TEST(SwathCoverage, HalfOrMoreIsNotWarnedOfAndTheFarSideIsNamed) {
  // 2 km across: 4009 .. 5773 m of 4000 .. 6000 m, 88 % of the cells.
  const Scene s = Scene::flat(60, 200, 10.0, 0.0f, 1);
  const SwathCoverage most = swath_coverage(west_track(s), s, swath(33.4e-6, 10e-6), 0.0);
  EXPECT_GT(most.cell_fraction, 0.85);
  EXPECT_FALSE(swath_coverage_warning(most).has_value());
  // The track 1 km farther west: the near 0.8 km of the scene.
  const SwathCoverage near = swath_coverage(west_track(s, 5000.0), s, swath(33.4e-6, 10e-6), 0.0);
  EXPECT_NEAR(near.across_imaged_m,
              std::sqrt(std::pow(swath(33.4e-6, 10e-6).far_m(), 2) - 9e6) - 5000.0, 1e-6);
  EXPECT_THAT(swath_coverage_warning(near).value_or(""),
              HasSubstr("0.8 km of the scene's 2.0 km across track (near side)"));
  // The swath from 40 us: u from 5191 m, the far 0.8 km.
  const SwathCoverage far = swath_coverage(west_track(s), s, swath(40e-6, 10e-6), 0.0);
  EXPECT_NEAR(far.across_imaged_m,
              6000.0 - std::sqrt(std::pow(swath(40e-6, 10e-6).near_m, 2) - 9e6), 1e-6);
  EXPECT_THAT(swath_coverage_warning(far).value_or(""),
              HasSubstr("0.8 km of the scene's 2.0 km across track (far side)"));
  // Raised ground (reference height 1000 m, H - h = 2000 m) and a 3 us
  // sweep: the band 4590 .. 5076 m, a strip in the middle.
  const SlantRangeBins narrow = swath(33.4e-6, 3e-6);
  const SwathCoverage raised = swath_coverage(west_track(s), s, narrow, 1000.0);
  EXPECT_NEAR(
      raised.across_imaged_m,
      std::sqrt(std::pow(narrow.far_m(), 2) - 4e6) - std::sqrt(std::pow(narrow.near_m, 2) - 4e6),
      1e-6);
  const auto w = swath_coverage_warning(raised);
  ASSERT_TRUE(w.has_value());
  EXPECT_THAT(*w, HasSubstr("across track (a strip in the middle)"));
  EXPECT_THAT(*w, HasSubstr("at the reference height 1000 m"));
}

TEST(SwathCoverage, AShortTrackIsWarnedOfAlongTrack) {
  // A track from y = 0 to 200 m over a scene 1000 m long: a fifth along.
  const Scene s = Scene::flat(100, 200, 10.0, 0.0f, 1);
  TrackSpec spec;
  spec.kind = TrackSpec::Kind::endpoints;
  spec.altitude_m = 3000.0;
  spec.start_x_m = -4000.0;
  spec.end_x_m = -4000.0;
  spec.start_y_m = 0.0;
  spec.end_y_m = 200.0;
  const Track t = resolve_track(spec, s, "radar.toml");
  const SwathCoverage c = swath_coverage(t, s, swath(33.4e-6, 10e-6), 0.0);
  EXPECT_NEAR(c.along_imaged_m, 200.0, 1e-6);
  EXPECT_NEAR(c.along_scene_m, 1000.0, 1e-6);
  const auto w = swath_coverage_warning(c);
  ASSERT_TRUE(w.has_value());
  EXPECT_THAT(*w, HasSubstr("and 0.2 km of its 1.0 km along track"));
  EXPECT_THAT(*w, HasSubstr("lengthen the track (track.start, track.end)"));
}

}  // namespace
}  // namespace ris
