// Closed-form anchors for ris topo on geographic (EPSG:4326) DEMs (issue 34,
// docs/geometry.md, "Geographic DEMs: closed-form anchors"): a plane of
// known slope and aspect around the scene centre, at latitudes 0, 45 and 70
// deg, facing east (towards the radar), north (along track) and north-east;
// the local incidence of every pixel within 0.01 deg of the closed form in
// ENU (tests/geographic_plane.h), the layover/shadow mask as the plane's, and
// a steep plane facing the radar (layover everywhere) or away from it
// (shadow everywhere).
//
// Tolerance budget (0.01 deg): the closed form holds the frame's rotation
// from the centre to each point exactly, so what is left is ris's own
// approximations: central differences over one posting of a bilinear DEM
// (exact for heights linear in latitude and longitude; the curvature of a
// plane in lat/lon over one 31 m posting leaves below 1e-5 deg), the
// posting steps taken at height 0 (N cos(lat), M) where the point is at
// height h: a relative slope error h / R, 1e-4 at 700 m, 0.003 deg at
// 45 deg of slope; float32 heights (1e-7 relative) and rdr2geo's ground
// point (its range within 1 mm). A slip of the east posting step by
// cos(latitude) moves local incidence by degrees at 45 and 70 deg.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "geographic_plane.h"
#include "ris/geometry/topo.h"
#include "test_util.h"

namespace ris {
namespace {

struct Outcome {
  std::size_t pixels = 0, mask_differs = 0, layover = 0, shadow = 0;
  double max_local_deg = 0.0, max_range_m = 0.0, max_height_m = 0.0;
  std::uint8_t expected_mask_any = 0;
};

Outcome run_topo(double lat_deg, double slope_deg, double aspect_deg) {
  test::TempDir dir;
  const Acquisition a = test::plane_acquisition(dir.path(), lat_deg);
  const test::GeographicPlane plane(a, slope_deg, aspect_deg);
  const EllipsoidalDem dem = plane.write_dem(a, dir / "plane.tif", 0.03);
  const TopoLayers t = compute_topo(a, dem, {});
  Outcome o;
  const GridWindow& w = t.window;
  for (std::size_t i = 0; i < t.lat_deg.size(); ++i) {
    if (!std::isfinite(t.lat_deg[i])) continue;
    const int line = w.line0 + static_cast<int>(i) / w.bins;
    const int bin = w.bin0 + static_cast<int>(i) % w.bins;
    const double lat = deg_to_rad(t.lat_deg[i]), lon = deg_to_rad(t.lon_deg[i]);
    const auto x = plane.expected(a, a.grid.time_of_line(line), lat, lon);
    ++o.pixels;
    o.max_local_deg =
        std::max(o.max_local_deg, std::abs(t.local_incidence_deg[i] - x.local_incidence_deg));
    o.max_range_m = std::max(o.max_range_m, std::abs(x.range_m - a.grid.range_of_bin(bin)));
    o.max_height_m = std::max(o.max_height_m, std::abs(t.height_m[i] - plane.height_m(lat, lon)));
    o.mask_differs += t.mask[i] != x.mask;
    o.layover += (t.mask[i] & kMaskLayover) != 0;
    o.shadow += (t.mask[i] & kMaskShadow) != 0;
    o.expected_mask_any |= x.mask;
  }
  std::printf(
      "topo lat %4.1f slope %4.1f aspect %5.1f: %zu pixels, local incidence within "
      "%.5f deg, range %.4f m, height %.4f m; mask differs on %zu (layover %zu, shadow %zu)\n",
      lat_deg, slope_deg, aspect_deg, o.pixels, o.max_local_deg, o.max_range_m, o.max_height_m,
      o.mask_differs, o.layover, o.shadow);
  return o;
}

class GeographicPlaneTopo : public ::testing::TestWithParam<double> {};

TEST_P(GeographicPlaneTopo, LocalIncidenceAndMaskAsTheClosedForm) {
  const double lat = GetParam();
  for (const double aspect : {90.0, 0.0, 45.0}) {
    const Outcome o = run_topo(lat, 15.0, aspect);
    EXPECT_EQ(o.pixels, 40U * 60U) << aspect;
    EXPECT_LT(o.max_local_deg, 0.01) << "aspect " << aspect;
    EXPECT_LT(o.max_range_m, 0.01) << aspect;   // the ground point is at the bin's range
    EXPECT_LT(o.max_height_m, 0.01) << aspect;  // and on the plane
    EXPECT_EQ(o.expected_mask_any, kMaskNone);  // a 15-deg plane: no layover, no shadow
    EXPECT_EQ(o.mask_differs, 0U) << aspect;
  }
}

INSTANTIATE_TEST_SUITE_P(Latitudes, GeographicPlaneTopo, ::testing::Values(0.0, 45.0, 70.0));

TEST(GeographicPlaneTopoMask, SteepPlanesFacingTheRadarLayOverAndFacingAwayAreShadowed) {
  // Facing the radar (east) at 50 deg, steeper than the 38.6-41.7 deg
  // incidence: the slant range falls along the plane's trace up to the foot
  // of the perpendicular from the sensor (look 50 deg) and grows beyond it,
  // so every range the plane reaches is reached twice: layover on every
  // pixel with ground (and ranges below the perpendicular's have none).
  const Outcome lay = run_topo(45.0, 50.0, 90.0);
  EXPECT_GT(lay.pixels, 1000U);
  EXPECT_EQ(lay.layover, lay.pixels);
  EXPECT_EQ(lay.shadow, 0U);
  EXPECT_LT(lay.max_local_deg, 0.01);
  // Facing away (west) at 55 deg, steeper than 90 deg less the incidence:
  // every facet back-facing, each hidden by the plane nearer the radar.
  const Outcome sh = run_topo(70.0, 55.0, 270.0);
  EXPECT_GT(sh.pixels, 1000U);
  EXPECT_EQ(sh.expected_mask_any, kMaskShadow);
  EXPECT_EQ(sh.shadow, sh.pixels);
  EXPECT_EQ(sh.layover, 0U);
  EXPECT_LT(sh.max_local_deg, 0.01);
}

}  // namespace
}  // namespace ris
