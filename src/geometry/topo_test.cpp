#include "ris/geometry/topo.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "acquisition_paths.h"
#include "acquisition_test_dems.h"
#include "ris/util/units.h"

namespace ris {
namespace {

using test::dem_for;
using test::small_airborne;

// Flat ground: the gamma area is the ground area projected on the plane
// normal to the look, i.e. beta area x cot(incidence) (Small 2011, eq. 8
// with a level facet), and the Muhleman amplitude is sqrt(sigma0 / sin(inc)).
TEST(Topo, FlatGroundAreaAndAmplitudeAreAnalytic) {
  const Acquisition a = small_airborne();
  const EllipsoidalDem dem = dem_for(a, 0.0, 1.0);
  const TopoLayers t = compute_topo(a, dem, {});
  ASSERT_EQ(t.window.lines, 60);
  ASSERT_EQ(t.window.bins, 300);
  EXPECT_EQ(t.unconverged, 0U);
  double sum_ratio = 0.0, sum_amp = 0.0, worst_local = 0.0;
  int n = 0;
  for (int l = 5; l < 55; ++l) {
    for (int b = 5; b < 295; ++b) {
      const std::size_t i = static_cast<std::size_t>(l) * 300 + b;
      const double inc = deg_to_rad(t.incidence_deg[i]);
      sum_ratio += t.gamma_area_m2[i] / (t.beta_area_m2 / std::tan(inc));
      const double c = std::cos(inc), s = std::sin(inc), d = s + 0.111 * c;
      sum_amp += t.simulated_amplitude[i] / std::sqrt(0.0118 * c / (d * d * d) / s);
      worst_local =
          std::max(worst_local,
                   static_cast<double>(std::abs(t.local_incidence_deg[i] - t.incidence_deg[i])));
      EXPECT_EQ(t.mask[i], 0);
      ++n;
    }
  }
  std::printf("flat: gamma area / analytic %.5f, amplitude / analytic %.5f, local-inc %.2g deg\n",
              sum_ratio / n, sum_amp / n, worst_local);
  EXPECT_NEAR(sum_ratio / n, 1.0, 5e-4);  // measured 1.00004
  EXPECT_NEAR(sum_amp / n, 1.0, 5e-4);    // measured 1.00003
  EXPECT_LT(worst_local, 1e-3);           // level ground: local = ellipsoid incidence
}

// Flat Earth vs ellipsoid: the incidence to the local vertical exceeds the
// look angle (the incidence a flat Earth would give) by the angle between the
// verticals at the nadir and at the target, u / R for a ground distance u.
TEST(Topo, EllipsoidIncidenceExceedsFlatEarthByGroundAngle) {
  const Acquisition a = small_airborne();
  const TopoLayers t = compute_topo(a, dem_for(a, 0.0, 1.0), {});
  const Ellipsoid& e = a.ellipsoid;
  double worst = 0.0;
  for (int b = 0; b < 300; b += 30) {
    const std::size_t i = 30 * 300 + b;
    const OrbitState s = a.orbit.interpolate(a.grid.time_of_line(30));
    const Geodetic nadir = e.to_geodetic(s.position_m);
    const Vec3 n0 = e.to_ecef({nadir.lat_rad, nadir.lon_rad, 230.0});
    const Vec3 x = e.to_ecef({deg_to_rad(t.lat_deg[i]), deg_to_rad(t.lon_deg[i]), 230.0});
    const double r =
        std::sqrt(e.meridional_radius_m(nadir.lat_rad) * e.prime_vertical_radius_m(nadir.lat_rad));
    const double expected_deg = rad_to_deg((x - n0).norm() / r);
    const double got_deg = t.incidence_deg[i] - t.look_deg[i];
    EXPECT_GT(got_deg, 0.0);
    worst = std::max(worst, std::abs(got_deg - expected_deg) / expected_deg);
  }
  std::printf("incidence - look vs u/R: worst relative %.3g\n", worst);
  EXPECT_LT(worst, 1e-3);  // measured 1.1e-4 (ellipsoid vs sphere of radius sqrt(MN))
}

// A steep ridge: its radar-facing slope (60 deg, steeper than any incidence
// here) is laid over, its far slope (60 deg > 90 - incidence beyond 30 deg)
// casts a shadow; flat ground far from it is neither, and shadow has no echo.
TEST(Topo, RidgeHasLayoverAndShadow) {
  const Acquisition a = small_airborne();
  const TopoLayers t = compute_topo(a, dem_for(a, 1500.0, 866.0), {});
  std::size_t shadow = 0, layover = 0;
  double shadow_bin = 0.0, layover_bin = 0.0;
  for (std::size_t i = 0; i < t.mask.size(); ++i) {
    shadow += (t.mask[i] & kMaskShadow) != 0;
    layover += (t.mask[i] & kMaskLayover) != 0;
    if ((t.mask[i] & kMaskShadow) != 0) shadow_bin += static_cast<double>(i % 300);
    if ((t.mask[i] & kMaskLayover) != 0) layover_bin += static_cast<double>(i % 300);
    if ((t.mask[i] & kMaskShadow) != 0) {
      EXPECT_EQ(t.simulated_amplitude[i], 0.0F);
    }
  }
  EXPECT_GT(shadow, 60U * 10U);
  EXPECT_GT(layover, 60U * 10U);
  // The crest is laid over towards near range, the shadow falls beyond it.
  EXPECT_LT(layover_bin / static_cast<double>(layover), 150.0);
  EXPECT_GT(shadow_bin / static_cast<double>(shadow), 150.0);
  const std::size_t mid = 30 * 300;
  EXPECT_EQ(t.mask[mid + 2], 0);    // near range, flat
  EXPECT_EQ(t.mask[mid + 297], 0);  // far range, beyond the shadow
}

TEST(Topo, SameBytesForOneAndTwoThreads) {
  const Acquisition a = small_airborne();
  const EllipsoidalDem dem = dem_for(a, 800.0, 1500.0);
  TopoOptions o1, o2;
  o1.threads = 1;
  o2.threads = 2;
  const TopoLayers t1 = compute_topo(a, dem, o1), t2 = compute_topo(a, dem, o2);
  const auto same = [](const auto& x, const auto& y) {
    return x.size() == y.size() && std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0;
  };
  EXPECT_TRUE(same(t1.lat_deg, t2.lat_deg));
  EXPECT_TRUE(same(t1.height_m, t2.height_m));
  EXPECT_TRUE(same(t1.local_incidence_deg, t2.local_incidence_deg));
  EXPECT_TRUE(same(t1.mask, t2.mask));
  EXPECT_TRUE(same(t1.gamma_area_m2, t2.gamma_area_m2));
  EXPECT_TRUE(same(t1.simulated_amplitude, t2.simulated_amplitude));
}

}  // namespace
}  // namespace ris
