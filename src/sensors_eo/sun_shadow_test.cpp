#include "ris/sensors_eo/sun_shadow.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ris/objects/mesh.h"

namespace ris {
namespace {

// A closed box [x0,x1] x [y0,y1] x [0,h].
void add_box(TriangleMesh& m, double x0, double x1, double y0, double y1, double h) {
  const Vec3 a{x0, y0, 0}, b{x1, y0, 0}, c{x1, y1, 0}, d{x0, y1, 0};
  const Vec3 at{x0, y0, h}, bt{x1, y0, h}, ct{x1, y1, h}, dt{x0, y1, h};
  m.add_quad(at, bt, ct, dt);  // roof
  m.add_quad(a, b, bt, at);
  m.add_quad(b, c, ct, bt);
  m.add_quad(c, d, dt, ct);
  m.add_quad(d, a, at, dt);
}

// Shadow length on flat ground behind a box of height h: h / tan(elevation),
// on the side away from the sun's azimuth. Sampled every 0.05 m along the
// line through the box's centre; the lit/shadow edge must be within 0.1 m.
void check_shadow(double azimuth_deg, double elevation_deg) {
  const double h = 10.0;
  TriangleMesh m;
  m.add_quad({-200, -200, 0}, {200, -200, 0}, {200, 200, 0}, {-200, 200, 0});  // ground
  add_box(m, -5, 5, -5, 5, h);
  const EmbreeScene scene(m);
  const Vec3 s = sun_direction_enu(azimuth_deg, elevation_deg);
  const double len = h / std::tan(elevation_deg * std::numbers::pi / 180.0);
  // Away from the sun: direction -(s.x, s.y) normalised; the box's face on
  // that side is 5 m from the centre along the axes used below.
  const double ux = -s.x / std::hypot(s.x, s.y);
  const double uy = -s.y / std::hypot(s.x, s.y);
  double last_shadow = 0;
  for (double r = 5.05; r < 5.0 + 3 * len; r += 0.05) {
    if (!sun_visible(scene, {r * ux, r * uy, 0.0}, s)) last_shadow = r;
  }
  EXPECT_NEAR(last_shadow - 5.0, len, 0.1) << "az " << azimuth_deg << " el " << elevation_deg;
  // Towards the sun: lit right next to the box.
  EXPECT_TRUE(sun_visible(scene, {-6.0 * ux, -6.0 * uy, 0.0}, s));
}

TEST(SunShadow, BoxShadowLengthIsHeightOverTanElevation) {
  check_shadow(90.0, 45.0);   // sun in the east: shadow 10 m to the west
  check_shadow(180.0, 30.0);  // sun in the south: 17.3 m to the north
  check_shadow(270.0, 60.0);  // west, 5.77 m to the east
  check_shadow(0.0, 20.0);    // north, 27.5 m to the south
}

TEST(SunShadow, SunDirectionAxes) {
  const Vec3 e = sun_direction_enu(90.0, 0.0);
  EXPECT_NEAR(e.x, 1.0, 1e-12);
  EXPECT_NEAR(e.y, 0.0, 1e-12);
  const Vec3 z = sun_direction_enu(123.0, 90.0);
  EXPECT_NEAR(z.z, 1.0, 1e-12);
}

}  // namespace
}  // namespace ris
