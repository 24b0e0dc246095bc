// The closed-form anchors of geometry on geographic DEMs (issue 34;
// src/geometry/geographic_anchor_test.cpp, tests/geographic_plane.h)
// through the `ris topo` binary: the plane's GeoTIFF in EPSG:4326 and the
// flight line's TOML written to a temporary folder, `ris topo` run on them,
// and its local_incidence.tif and layover_shadow_mask.tif read back at the
// ground point of lat.tif / lon.tif against the closed form in ENU (0.01
// deg; the library test's budget, plus float32 storage of the incidence,
// 4e-6 deg at 45 deg). What this adds to the library test: the command's
// own reading of the DEM and the acquisition, its window and its writers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "geographic_plane.h"
#include "ris/io/raster_io.h"
#include "test_util.h"

namespace ris {
namespace {

struct CliOutcome {
  std::size_t pixels = 0, mask_differs = 0, layover = 0, shadow = 0;
  double max_local_deg = 0.0;
};

CliOutcome run_topo_cli(double lat_deg, double slope_deg, double aspect_deg) {
  test::TempDir dir;
  const Acquisition a = test::plane_acquisition(dir.path(), lat_deg);
  const test::GeographicPlane plane(a, slope_deg, aspect_deg);
  plane.write_dem(a, dir / "plane.tif", 0.03);
  const auto r =
      test::run_ris("topo --quiet --acquisition " + test::q(dir / "flight.toml") + " --dem " +
                    test::q(dir / "plane.tif") + " --out " + test::q(dir / "topo"));
  EXPECT_EQ(r.exit_code, 0) << r.output;
  CliOutcome o;
  if (r.exit_code != 0) return o;
  const RasterF64 lat = read_raster_f64(dir / "topo" / "lat.tif");
  const RasterF64 lon = read_raster_f64(dir / "topo" / "lon.tif");
  const RasterF64 local = read_raster_f64(dir / "topo" / "local_incidence.tif");
  const RasterF64 mask = read_raster_f64(dir / "topo" / "layover_shadow_mask.tif");
  const int line0 = std::stoi(lat.metadata.at("RIS_WINDOW_FIRST_LINE"));
  for (std::size_t i = 0; i < lat.data.size(); ++i) {
    if (!std::isfinite(lat.data[i])) continue;
    const int line = line0 + static_cast<int>(i) / lat.cols;
    const auto x = plane.expected(a, a.grid.time_of_line(line), deg_to_rad(lat.data[i]),
                                  deg_to_rad(lon.data[i]));
    ++o.pixels;
    o.max_local_deg = std::max(o.max_local_deg, std::abs(local.data[i] - x.local_incidence_deg));
    const auto m = static_cast<std::uint8_t>(mask.data[i]);
    o.mask_differs += m != x.mask;
    o.layover += (m & kMaskLayover) != 0;
    o.shadow += (m & kMaskShadow) != 0;
  }
  std::printf(
      "ris topo lat %4.1f slope %4.1f aspect %5.1f: %zu pixels, local incidence within %.5f "
      "deg; mask differs on %zu (layover %zu, shadow %zu)\n",
      lat_deg, slope_deg, aspect_deg, o.pixels, o.max_local_deg, o.mask_differs, o.layover,
      o.shadow);
  return o;
}

class TopoCliGeographicPlane : public ::testing::TestWithParam<double> {};

TEST_P(TopoCliGeographicPlane, LocalIncidenceAndMaskAsTheClosedForm) {
  for (const double aspect : {90.0, 0.0, 45.0}) {  // east (towards the radar), north, north-east
    const CliOutcome o = run_topo_cli(GetParam(), 15.0, aspect);
    EXPECT_EQ(o.pixels, 40U * 60U) << aspect;
    EXPECT_LT(o.max_local_deg, 0.01) << "aspect " << aspect;
    EXPECT_EQ(o.mask_differs, 0U) << aspect;  // no layover, no shadow on a 15-deg plane
  }
}

INSTANTIATE_TEST_SUITE_P(Latitudes, TopoCliGeographicPlane, ::testing::Values(0.0, 45.0, 70.0));

TEST(TopoCliGeographicPlaneMask, SteepPlanesLayOverFacingTheRadarAndAreShadowedFacingAway) {
  const CliOutcome lay = run_topo_cli(45.0, 50.0, 90.0);  // steeper than the 38.6-41.7 deg look
  EXPECT_GT(lay.pixels, 1000U);
  EXPECT_EQ(lay.layover, lay.pixels);
  EXPECT_EQ(lay.mask_differs, 0U);
  EXPECT_LT(lay.max_local_deg, 0.01);
  const CliOutcome sh = run_topo_cli(70.0, 55.0, 270.0);  // back-facing everywhere
  EXPECT_GT(sh.pixels, 1000U);
  EXPECT_EQ(sh.shadow, sh.pixels);
  EXPECT_EQ(sh.mask_differs, 0U);
  EXPECT_LT(sh.max_local_deg, 0.01);
}

}  // namespace
}  // namespace ris
