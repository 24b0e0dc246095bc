// Closed-form anchors for an acquisition run on geographic (EPSG:4326) DEMs
// (issue 34; docs/geometry.md, "Geographic DEMs: closed-form anchors"): the
// planes of src/geometry/geographic_anchor_test.cpp (tests/geographic_plane.h)
// through `simulate_acquisition`, whose local incidence layer (the terrain
// sample nearest each bin's centre) and layover/shadow mask must match the
// closed form in ENU at the bin's ground point (ris topo's rdr2geo, itself
// checked against the closed form there) within 0.01 deg.
//
// Tolerance budget beyond topo's (0.007 deg): the run's layer is its
// terrain sample nearest the bin's centre, up to a sixth of a bin (3
// samples a bin) away, where the incidence changes by 0.05 deg a bin on
// these grids: asked for 9 samples a bin, that is under 0.003 deg.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "build_paths.h"
#include "geographic_plane.h"
#include "ris/backscatter/library.h"
#include "ris/geometry/topo.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/acquisition_simulation.h"
#include "test_util.h"

namespace ris {
namespace {

// 200 bins (2.5 km of slant range from 16 km, 38.6-47.5 deg of incidence):
// the run's terrain profile spans the look angles from the near range at the
// DEM's highest point to the far range at its lowest, which must not cross
// (docs/geometry.md: a DEM whose relief exceeds that is not handled yet).
constexpr int kBins = 200;

struct Outcome {
  std::size_t pixels = 0, mask_differs = 0, layover = 0, shadow = 0;
  double max_local_deg = 0.0;
};

Outcome run_acquisition(double lat_deg, double slope_deg, double aspect_deg) {
  test::TempDir dir;
  const Acquisition a = test::plane_acquisition(dir.path(), lat_deg, kBins);
  const test::GeographicPlane plane(a, slope_deg, aspect_deg);
  const EllipsoidalDem dem = plane.write_dem(a, dir / "plane.tif", 0.005);
  const RadarParams radar = load_radar(std::string(test::data_dir()) + "/radars/seed-fig4-5.toml");
  const auto sigma0 =
      load_sigma0_source(std::string(test::data_dir()) + "/backscatter/ku-geometric.toml");
  AcquisitionSimOptions options;
  options.samples_per_bin = 9;
  const AcquisitionSimulation s = simulate_acquisition(a, dem, radar, *sigma0, options);
  const TopoLayers t = compute_topo(a, dem, {});
  EXPECT_EQ(s.window.line0, t.window.line0);
  EXPECT_EQ(s.window.bin0, t.window.bin0);
  EXPECT_EQ(s.local_incidence_deg.size(), t.lat_deg.size());
  Outcome o;
  const GridWindow& w = t.window;
  for (std::size_t i = 0; i < std::min(t.lat_deg.size(), s.local_incidence_deg.size()); ++i) {
    if (!std::isfinite(t.lat_deg[i]) || !std::isfinite(s.local_incidence_deg[i])) continue;
    const int line = w.line0 + static_cast<int>(i) / w.bins;
    const auto x = plane.expected(a, a.grid.time_of_line(line), deg_to_rad(t.lat_deg[i]),
                                  deg_to_rad(t.lon_deg[i]));
    ++o.pixels;
    o.max_local_deg =
        std::max(o.max_local_deg, std::abs(s.local_incidence_deg[i] - x.local_incidence_deg));
    o.mask_differs += s.layover_shadow_mask[i] != x.mask;
    o.layover += (s.layover_shadow_mask[i] & kMaskLayover) != 0;
    o.shadow += (s.layover_shadow_mask[i] & kMaskShadow) != 0;
  }
  std::printf(
      "acquisition lat %4.1f slope %4.1f aspect %5.1f: %zu pixels, local incidence "
      "within %.5f deg; mask differs on %zu (layover %zu, shadow %zu)\n",
      lat_deg, slope_deg, aspect_deg, o.pixels, o.max_local_deg, o.mask_differs, o.layover,
      o.shadow);
  return o;
}

class GeographicPlaneAcquisition : public ::testing::TestWithParam<double> {};

TEST_P(GeographicPlaneAcquisition, LocalIncidenceAndMaskAsTheClosedForm) {
  for (const double aspect : {90.0, 0.0, 45.0}) {
    const Outcome o = run_acquisition(GetParam(), 15.0, aspect);
    EXPECT_GT(o.pixels, 40U * kBins * 9 / 10) << aspect;  // the DEM leaves a few bins at the edge
    EXPECT_LT(o.max_local_deg, 0.01) << "aspect " << aspect;
    EXPECT_EQ(o.mask_differs, 0U) << aspect;  // a 15-deg plane: no layover, no shadow
  }
}

INSTANTIATE_TEST_SUITE_P(Latitudes, GeographicPlaneAcquisition, ::testing::Values(0.0, 45.0, 70.0));

}  // namespace
}  // namespace ris
