#include "ris/sensor/track.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

TEST(Track, HeadingNorthRightLookingSeesEastAtNearEdgeDistance) {
  Scene s = Scene::flat(700, 1000, 6.096, 0.0f, 0);
  TrackSpec spec;
  spec.heading_rad = 0.0;
  spec.near_edge_ground_m = 109900 * kFeetToMetres;
  spec.altitude_m = 40000 * kFeetToMetres;
  Track t = resolve_track(spec, s, "r.toml");
  EXPECT_NEAR(t.cross_x, 1.0, 1e-12);
  EXPECT_NEAR(t.cross_y, 0.0, 1e-12);
  // West edge (x = 0) is the near edge: u = GROUND(1) there.
  auto [s_w, u_w] = t.along_cross(0.0, 100.0);
  EXPECT_NEAR(u_w, spec.near_edge_ground_m, 1e-6);
  // The track covers the scene's rows: south edge s = 0, north edge s = length.
  EXPECT_NEAR(t.along_cross(0.0, 0.0).first, 0.0, 1e-6);
  EXPECT_NEAR(t.length_m, 700 * 6.096, 1e-6);
  (void)s_w;
}

TEST(Track, LeftLookingHeadingEastLooksNorth) {
  Scene s = Scene::flat(10, 10, 1.0, 0.0f, 0);
  TrackSpec spec;
  spec.heading_rad = kPi / 2;
  spec.look_side = LookSide::left;
  spec.near_edge_ground_m = 100.0;
  spec.altitude_m = 50.0;
  Track t = resolve_track(spec, s, "r.toml");
  EXPECT_NEAR(t.cross_x, 0.0, 1e-12);
  EXPECT_NEAR(t.cross_y, 1.0, 1e-12);
  EXPECT_NEAR(t.along_cross(5.0, 0.0).second, 100.0, 1e-9);  // south edge is near
}

TEST(Track, EndpointsAndBadInput) {
  Scene s = Scene::flat(10, 10, 1.0, 0.0f, 0);
  TrackSpec spec;
  spec.kind = TrackSpec::Kind::endpoints;
  spec.start_x_m = -100;
  spec.start_y_m = 0;
  spec.end_x_m = -100;
  spec.end_y_m = 10;
  spec.altitude_m = 100;
  Track t = resolve_track(spec, s, "r.toml");
  EXPECT_NEAR(t.along_cross(0.0, 5.0).second, 100.0, 1e-12);
  spec.end_y_m = 0;
  EXPECT_THROW(resolve_track(spec, s, "r.toml"), InputError);
  spec.end_y_m = 10;
  spec.altitude_m = -1;
  EXPECT_THROW(resolve_track(spec, s, "r.toml"), InputError);
}

}  // namespace
}  // namespace ris
