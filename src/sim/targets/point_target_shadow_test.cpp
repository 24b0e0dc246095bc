// A point target behind a wall (issue 22's anchor for the target shadow test,
// MODEL.md section 2 "Cast shadow" at the target's own height): seen above
// the wall's shadow line, hidden below it, at the predicted slant range and
// with the predicted power when seen.
//
// Flat ground under a track 3000 m up, 4000 m west of the scene; a 100 m wall
// across the whole scene at x 500-520 m (ground range u 4500-4520 m). Its
// top's farthest sample (the cell centre at u_w = 4515 m) casts the shadow
// line h_s(u) = H - (H - W) u / u_w behind it, down to the ground at
// u = u_w H / (H - W) = 4670.7 m.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ris/image/greytone_terms.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/point_target.h"
#include "ris/sim/slar_simulation.h"
#include "slar_fixtures.h"
#include "test_inputs.h"

namespace ris {
namespace {

constexpr double kH = 3000.0, kWall = 100.0, kTrackX = -4000.0, kWallFarU = 4515.0;

double shadow_line_m(double u) {
  return kH - (kH - kWall) * u / kWallFarU;
}

PointTarget target(const std::string& name, double u, double height_m) {
  PointTarget t;
  t.name = name;
  t.x_m = u + kTrackX;
  t.y_m = 205.0;  // mid-scene, a cell centre's line
  t.height_m = height_m;
  t.rcs_m2 = 100.0;
  return t;
}

TEST(PointTargetShadow, TargetBehindAWallIsSeenAboveTheShadowLineAndHiddenBelow) {
  Scene s = Scene::flat(40, 200, 10.0, 0.0f, 1);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 50; c < 52; ++c) s.elevation_m[s.index(r, c)] = float(kWall);
  const RadarParams radar = radar_from_toml(toml::parse(test::kSmallSlarRadar), "r.toml");

  // Pairs 2 m above and below the shadow line at two distances, one target
  // on open ground inside the shadow and one beyond its end.
  SlarOptions o;
  const double u1 = 4560.0, u2 = 4640.0;
  o.targets = {target("above-1", u1, shadow_line_m(u1) + 2.0),
               target("below-1", u1, shadow_line_m(u1) - 2.0),
               target("above-2", u2, shadow_line_m(u2) + 2.0),
               target("below-2", u2, shadow_line_m(u2) - 2.0),
               target("ground-in-shadow", 4600.0, 0.0),
               target("ground-beyond", 4700.0, 0.0)};
  const SlarSimulation sim = simulate_slar(s, radar, test::CosineSigma0Source(), o);

  std::vector<std::string> hidden = sim.hidden_targets;
  std::sort(hidden.begin(), hidden.end());
  EXPECT_EQ(hidden, (std::vector<std::string>{"below-1", "below-2", "ground-in-shadow"}));

  // The seen ones at R = sqrt(u^2 + (H - h)^2), each adding the radar
  // equation's power with sigma in place of sigma0 A.
  ASSERT_EQ(sim.point_returns.size(), 3u);
  ASSERT_EQ(sim.image.point_power_w.size(), 3u);
  const std::vector<std::pair<double, double>> seen = {
      {u1, shadow_line_m(u1) + 2.0}, {u2, shadow_line_m(u2) + 2.0}, {4700.0, 0.0}};
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const auto [u, h] = seen[i];
    const double R = std::hypot(u, kH - h);
    EXPECT_NEAR(sim.point_returns[i].slant_range_m, R, 1e-6) << i;
    const double want = radar_equation_power_w(radar.transmit_power_w, 100.0, 1.0, radar.peak_gain,
                                               radar.wavelength_m(), R);
    EXPECT_NEAR(sim.image.point_power_w[i] / want, 1.0, 1e-9) << i;
  }
}

}  // namespace
}  // namespace ris
