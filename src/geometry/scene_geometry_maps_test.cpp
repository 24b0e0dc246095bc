#include "ris/geometry/scene_geometry_maps.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

constexpr double kCell = 6.0, kH = 3000.0, kNear = 4000.0;

TEST(SceneGeometryMaps, FlagsAndLocalIncidenceLandOnTheirCells) {
  Scene s = Scene::flat(10, 200, kCell, 0.0f, 1);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 80; c < 90; ++c) s.elevation_m[s.index(r, c)] = 150.0f;
  s.valid[s.index(2, 30)] = 0;
  s.elevation_m[s.index(2, 30)] = std::nanf("");
  const SlarGeometry g = compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "r");
  // Swath covers u up to ~4900 m (column ~150): the rest is outside.
  const SlantRangeBins bins{std::hypot(kNear, kH), 10.0, 50};
  const SceneGeometryMaps m = scene_geometry_maps(s, g, bins);
  const auto at = [&](int r, int c) { return m.mask[s.index(r, c)]; };
  EXPECT_EQ(at(5, 10), 0);
  EXPECT_EQ(at(2, 30), scene_flag::kNoData);
  EXPECT_TRUE(std::isnan(m.local_incidence_deg[s.index(2, 30)]));
  EXPECT_TRUE(at(5, 95) & scene_flag::kShadow);      // behind the box
  EXPECT_TRUE(at(5, 89) & scene_flag::kBackFacing);  // the box's far wall cell
  EXPECT_TRUE(at(5, 79) & scene_flag::kLayover);     // ground before the box
  const double far_u = std::sqrt(std::pow(bins.far_m(), 2) - kH * kH);
  const int first_out = static_cast<int>(std::ceil((far_u - kNear) / kCell - 0.5));
  EXPECT_FALSE(at(5, first_out - 1) & scene_flag::kOutsideSwath);
  EXPECT_TRUE(at(5, first_out) & scene_flag::kOutsideSwath);
  // Local incidence in degrees equals the geometry's, cell by cell.
  for (int c = 0; c < s.cols; c += 7) {
    const std::size_t i = g.index(s.rows - 1 - 5, c);
    EXPECT_NEAR(m.local_incidence_deg[s.index(5, c)], rad_to_deg(g.local_incidence_rad[i]), 1e-4);
  }
}

}  // namespace
}  // namespace ris

namespace ris {
namespace {

TEST(SceneGeometryMaps, RoundHalfAwayIsStdRound) {
  for (double x : {0.0, 0.3, -0.3, 0.5, -0.5, 1.5, -1.5, 2.5, -2.5, 0.49999999999999994,
                   -0.49999999999999994, 1e12 + 0.5, -1e12 - 0.5, 4503599627370495.5}) {
    EXPECT_EQ(round_half_away(x), std::round(x)) << x;
  }
  for (int i = -100000; i <= 100000; ++i) {
    const double x = i * 0.0137 + 1e-3 * std::sin(i);
    ASSERT_EQ(round_half_away(x), std::round(x)) << x;
  }
}

}  // namespace
}  // namespace ris
