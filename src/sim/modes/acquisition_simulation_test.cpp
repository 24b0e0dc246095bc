#include "ris/sim/acquisition_simulation.h"

#include <gtest/gtest.h>

#include <omp.h>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "acquisition_paths.h"
#include "acquisition_test_dems.h"
#include "ris/backscatter/library.h"
#include "ris/geometry/topo.h"
#include "ris/scene/geo_frame.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/units.h"
#include "sim/sources/acquisition_lines.h"

namespace ris {
namespace {

RadarParams seed_radar() {
  return load_radar(std::string(test::data_dir()) + "/radars/seed-fig4-5.toml");
}

std::unique_ptr<Sigma0Source> standard_library() {
  return load_sigma0_source(std::string(test::data_dir()) + "/backscatter/ku-geometric.toml");
}

AcquisitionSimulation simulate(const Acquisition& a, const EllipsoidalDem& dem,
                               EarthModel earth = EarthModel::ellipsoid) {
  AcquisitionSimOptions o;
  o.earth = earth;
  return simulate_acquisition(a, dem, seed_radar(), *standard_library(), o);
}

// Local incidence of the simulation's layer against ris topo's on the same
// pixels: mean and largest absolute difference (degrees) where both have one.
struct Agreement {
  double mean_deg = 0.0, max_deg = 0.0;
  std::size_t n = 0;
};
Agreement local_incidence_agreement(const AcquisitionSimulation& s, const TopoLayers& t) {
  Agreement a;
  double sum = 0.0;
  for (std::size_t i = 0; i < t.local_incidence_deg.size(); ++i) {
    const double x = s.local_incidence_deg[i], y = t.local_incidence_deg[i];
    if (!std::isfinite(x) || !std::isfinite(y)) continue;
    sum += std::abs(x - y);
    a.max_deg = std::max(a.max_deg, std::abs(x - y));
    ++a.n;
  }
  a.mean_deg = a.n > 0 ? sum / static_cast<double>(a.n) : 0.0;
  return a;
}

// Winnipeg (UAVSAR, 250 x 250): the image has the product's grid, every
// pixel has terrain, and the local incidence agrees with ris topo's.
TEST(AcquisitionSimulation, WinnipegOnTheProductGridAgreesWithTopo) {
  const Acquisition a = read_acquisition(test::winnipeg_h5());
  const EllipsoidalDem dem = read_ellipsoidal_dem(test::test_dem("winnipeg_dem.tif"));
  const AcquisitionSimulation s = simulate(a, dem);
  ASSERT_EQ(s.sim.image.lines, 250);
  ASSERT_EQ(s.sim.image.bins, 250);
  EXPECT_EQ(s.window.line0, 0);
  EXPECT_EQ(s.window.bin0, 0);
  // Bin k's centre is the product's range sample k (its slantRange).
  EXPECT_DOUBLE_EQ(s.sim.image.range.centre_m(0), a.grid.near_range_m);
  EXPECT_DOUBLE_EQ(s.sim.image.range.centre_m(100), a.grid.range_of_bin(100));
  EXPECT_DOUBLE_EQ(s.sim.image.range.bin_m, a.grid.range_spacing_m);
  std::size_t with_power = 0;
  for (std::size_t i = 0; i < s.sim.image.mean_power_w.size(); ++i) {
    with_power +=
        (s.sim.image.mask[i] & pixel_flag::kNoData) == 0 && s.sim.image.mean_power_w[i] > 0.0f;
  }
  EXPECT_EQ(with_power, s.sim.image.mean_power_w.size());
  const TopoLayers t = compute_topo(a, dem, {});
  const Agreement ag = local_incidence_agreement(s, t);
  std::printf("winnipeg: local incidence vs topo: mean %.4f deg, max %.4f deg over %zu pixels\n",
              ag.mean_deg, ag.max_deg, ag.n);
  EXPECT_EQ(ag.n, 250U * 250U);
  EXPECT_LT(ag.mean_deg, 0.1);  // measured 0.045 (samples within 1/6 bin of the centre)
  EXPECT_LT(ag.max_deg, 1.0);   // measured 0.46
  for (std::size_t i = 0; i < t.mask.size(); ++i) EXPECT_EQ(s.layover_shadow_mask[i], t.mask[i]);
}

// Land cover: a UTM scene over Winnipeg, category 1 west of the grid's
// centre and 2 east of it. Pixels whose ground lies well west of the split have the
// power of an all-1 run, those well east of it the power of an all-2 run
// (the same terrain points, only sigma0 changes).
TEST(AcquisitionSimulation, LandCoverGivesEachPointItsCategory) {
  const Acquisition a = read_acquisition(test::winnipeg_h5());
  const EllipsoidalDem dem = read_ellipsoidal_dem(test::test_dem("winnipeg_dem.tif"));
  // Split at the ground of the grid's centre pixel.
  const TopoLayers t = compute_topo(a, dem, {});
  const double lon_c = t.lon_deg[125 * 250 + 125], lat_c = t.lat_deg[125 * 250 + 125];
  Scene cover = Scene::flat(400, 400, 25.0, 0.0f, 1);
  cover.crs_wkt = utm_wkt_for(lon_c, lat_c);
  const GeoFrame frame(cover.crs_wkt, "test");
  const auto [xc, yc] = frame.scene_from_lonlat(lon_c, lat_c);
  cover.origin_x_m = xc - 5000.0;
  cover.origin_y_m = yc + 5000.0;
  for (int r = 0; r < cover.rows; ++r)
    for (int c = 200; c < cover.cols; ++c) cover.category[cover.index(r, c)] = 2;
  const auto run = [&](std::uint16_t category, const Scene* land_cover) {
    AcquisitionSimOptions o;
    o.category = category;
    o.land_cover = land_cover;
    o.land_cover_source = "test";
    return simulate_acquisition(a, dem, seed_radar(), *standard_library(), o);
  };
  const AcquisitionSimulation mixed = run(1, &cover), one = run(1, nullptr), two = run(2, nullptr);
  EXPECT_EQ(mixed.sim.categories, (std::vector<std::uint16_t>{1, 2}));
  std::size_t west = 0, east = 0, wrong = 0;
  for (std::size_t i = 0; i < t.lat_deg.size(); ++i) {
    const double x = frame.scene_from_lonlat(t.lon_deg[i], t.lat_deg[i]).first - xc;
    if (std::abs(x) < 100.0 || std::abs(x) > 4800.0) continue;
    const float want = x < 0.0 ? one.sim.image.mean_power_w[i] : two.sim.image.mean_power_w[i];
    (x < 0.0 ? west : east) += 1;
    wrong += std::abs(mixed.sim.image.mean_power_w[i] - want) > 1e-5f * want;
  }
  std::printf("land cover: %zu pixels west, %zu east of the split, %zu with the other's power\n",
              west, east, wrong);
  EXPECT_GT(west, 5000U);
  EXPECT_GT(east, 5000U);
  EXPECT_EQ(wrong, 0U);
}

// A steep ridge (60-degree slopes) under the airborne example: layover
// before the crest and shadow behind it as in ris topo's mask, and the
// image dark there. Where the two masks differ, topo has no ground for the
// bin (its rdr2geo did not converge, or its profile left the bin empty on a
// back slope that faces away from the radar) and the simulation calls it
// shadow on a back-facing slope.
TEST(AcquisitionSimulation, RidgeShadowAndLayoverAsTopo) {
  const Acquisition a = test::small_airborne();
  const EllipsoidalDem dem = test::dem_for(a, 1500.0, 866.0);
  const AcquisitionSimulation s = simulate(a, dem);
  const TopoLayers t = compute_topo(a, dem, {});
  ASSERT_EQ(s.layover_shadow_mask.size(), t.mask.size());
  std::size_t same = 0, shadow = 0, layover = 0, dark = 0, back_slope = 0, other = 0, lit = 0;
  double lit_power = 0.0, local_sum = 0.0;
  for (std::size_t i = 0; i < t.mask.size(); ++i) {
    const std::uint8_t sm = s.layover_shadow_mask[i], tm = t.mask[i];
    same += sm == tm;
    layover += (tm & kMaskLayover) != 0;
    if (tm == kMaskShadow) {
      ++shadow;
      dark += (s.sim.image.mask[i] & pixel_flag::kShadow) != 0;
    }
    if (sm != tm && std::isfinite(t.height_m[i])) {
      const bool empty_back_slope =
          tm == kMaskNone && sm == kMaskShadow && s.local_incidence_deg[i] > 90.0f;
      (empty_back_slope ? back_slope : other) += 1;
    }
    if (tm == kMaskNone && sm == kMaskNone) {
      lit_power += s.sim.image.mean_power_w[i];
      local_sum += std::abs(s.local_incidence_deg[i] - t.local_incidence_deg[i]);
      ++lit;
    }
  }
  std::printf(
      "ridge: mask as topo's on %zu of %zu pixels; where topo has ground and they differ: "
      "%zu back-slope bins topo left empty, %zu others; %zu shadow (%zu dark), %zu "
      "layover; lit local incidence vs topo %.4f deg\n",
      same, t.mask.size(), back_slope, other, shadow, dark, layover,
      local_sum / static_cast<double>(lit));
  EXPECT_GT(shadow, 600U);
  EXPECT_GT(layover, 600U);
  // Measured: 9 others (the shadow's far edge, one bin in some lines).
  EXPECT_LT(static_cast<double>(other), 0.01 * static_cast<double>(shadow + layover));
  EXPECT_GT(static_cast<double>(dark),
            0.99 * static_cast<double>(shadow));  // measured 4492 of 4501
  EXPECT_GT(lit_power, 0.0);
  EXPECT_LT(local_sum / static_cast<double>(lit), 0.01);  // measured 0.0024 deg
}

// One line's samples through the acquisition source, as the engine sees them.
struct SourceLine {
  std::vector<float> range_m, local_incidence_rad;
  std::vector<double> ground_u_m;
  double nadir_radius_m = 0.0;
};
SourceLine load_line(const Acquisition& a, const EllipsoidalDem& dem, EarthModel earth, int line) {
  const GridWindow w{0, a.grid.lines, 0, a.grid.bins};
  detail::AcquisitionRun run{a, dem, w, earth, 1, nullptr, 230.0, 230.0, 3};
  run.max_points = detail::acquisition_max_points(run);
  SlarGeometry layout;
  layout.samples = static_cast<int>(run.max_points);
  layout.first_sample_u_m = layout.sample_step_m = 1.0;
  run.layout = &layout;
  std::vector<float> local(w.size());
  std::vector<std::uint8_t> mask(w.size());
  run.local_incidence_deg = local.data();
  run.mask = mask.data();
  detail::LineScratch s(layout, w.bins);
  detail::AcquisitionThreadSource ts{run, {}, {}, {}, {}, {}, {}, {}, {}};
  auto source = std::get<detail::AcquisitionLineSource>(ts.block(line, line + 1));
  const detail::LineSpan span = source.load(line, s);
  SourceLine out;
  out.range_m.assign(s.range.begin(), s.range.begin() + span.n);
  out.local_incidence_rad.assign(s.local_incidence.begin(), s.local_incidence.begin() + span.n);
  out.ground_u_m = ts.ground_u_m;
  const Geodetic nadir =
      a.ellipsoid.to_geodetic(a.orbit.interpolate(a.grid.time_of_line(line)).position_m);
  out.nadir_radius_m = std::sqrt(a.ellipsoid.meridional_radius_m(nadir.lat_rad) *
                                 a.ellipsoid.prime_vertical_radius_m(nadir.lat_rad));
  return out;
}

// Flat Earth vs ellipsoid, point by point on level ground (the airborne
// example, 12.5 km up): the incidence on the ellipsoid exceeds the flat
// Earth's by the ground angle u / R, less the change of the look angle
// itself: the curved ground lies lower by the drop d = u^2 / 2R, which turns
// the look by d sin(look) / R_slant and lengthens the slant range by about
// d cos(look).
TEST(AcquisitionSimulation, FlatAndEllipsoidDifferByTheGroundAngle) {
  const Acquisition a = test::small_airborne();
  const EllipsoidalDem dem = test::dem_for(a, 0.0, 1.0);
  const SourceLine ell = load_line(a, dem, EarthModel::ellipsoid, 30);
  const SourceLine flat = load_line(a, dem, EarthModel::flat, 30);
  ASSERT_EQ(ell.range_m.size(), flat.range_m.size());
  double worst_angle = 0.0, worst_range = 0.0, lo = 1e9, hi = 0.0;
  std::size_t n = 0;
  for (std::size_t k = 0; k < ell.range_m.size(); ++k) {
    if (!std::isfinite(ell.range_m[k]) || ell.ground_u_m[k] < 1000.0) continue;
    const double u = ell.ground_u_m[k], rad = ell.nadir_radius_m;
    const double got = ell.local_incidence_rad[k] - flat.local_incidence_rad[k];
    const double drop = u * u / (2.0 * rad);
    const double cos_look = (12500.0 - 230.0) / flat.range_m[k];
    const double sin_look = std::sqrt(1.0 - cos_look * cos_look);
    const double want = u / rad - drop * sin_look / flat.range_m[k];
    worst_angle = std::max(worst_angle, std::abs(got / want - 1.0));
    const double dr = static_cast<double>(ell.range_m[k]) - flat.range_m[k];
    worst_range = std::max(worst_range, std::abs(dr / (drop * cos_look) - 1.0));
    lo = std::min(lo, rad_to_deg(got));
    hi = std::max(hi, rad_to_deg(got));
    ++n;
  }
  std::printf(
      "flat vs ellipsoid: incidence differs by %.4f-%.4f deg, worst %.2g of the expected; range "
      "worst %.2g of the drop x cos(look), %zu points\n",
      lo, hi, worst_angle, worst_range, n);
  EXPECT_GT(n, 500U);
  EXPECT_LT(worst_angle, 0.05);
  EXPECT_LT(worst_range, 0.1);
}

// The flat Earth puts Winnipeg's terrain at other slant ranges (a few
// metres): the two images differ.
TEST(AcquisitionSimulation, FlatAndEllipsoidImagesDiffer) {
  const Acquisition a = read_acquisition(test::winnipeg_h5());
  const EllipsoidalDem dem = read_ellipsoidal_dem(test::test_dem("winnipeg_dem.tif"));
  const AcquisitionSimulation ell = simulate(a, dem, EarthModel::ellipsoid);
  const AcquisitionSimulation flat = simulate(a, dem, EarthModel::flat);
  double diff = 0.0, total = 0.0;
  for (std::size_t i = 0; i < ell.sim.image.mean_power_w.size(); ++i) {
    diff += std::abs(ell.sim.image.mean_power_w[i] - flat.sim.image.mean_power_w[i]);
    total += ell.sim.image.mean_power_w[i];
  }
  std::printf("flat vs ellipsoid: mean |power difference| / mean power %.4f\n", diff / total);
  EXPECT_GT(diff / total, 1e-3);
}

// Lines go to threads in blocks, each line written by one: the same bytes
// for one and two threads.
TEST(AcquisitionSimulation, SameBytesForOneAndTwoThreads) {
  const Acquisition a = test::small_airborne();
  const EllipsoidalDem dem = test::dem_for(a, 800.0, 1500.0);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const AcquisitionSimulation one = simulate(a, dem);
  omp_set_num_threads(2);
  const AcquisitionSimulation two = simulate(a, dem);
  omp_set_num_threads(threads);
  ASSERT_EQ(one.sim.image.mean_power_w.size(), two.sim.image.mean_power_w.size());
  EXPECT_EQ(std::memcmp(one.sim.image.mean_power_w.data(), two.sim.image.mean_power_w.data(),
                        one.sim.image.mean_power_w.size() * sizeof(float)),
            0);
  EXPECT_EQ(one.sim.image.mask, two.sim.image.mask);
  EXPECT_EQ(std::memcmp(one.local_incidence_deg.data(), two.local_incidence_deg.data(),
                        one.local_incidence_deg.size() * sizeof(float)),
            0);
  EXPECT_EQ(one.layover_shadow_mask, two.layover_shadow_mask);
}

// Sentinel-1 (the shipped IW SLC's sub-swath IW1) on a small DEM inside it:
// 1 arc-second postings over 41.70-41.75 N, 11.40-11.45 E, rolling hills.
TEST(AcquisitionSimulation, Sentinel1SubSwathOnASmallDem) {
  const Acquisition a = read_acquisition(test::sentinel1_safe());
  const double step = deg_to_rad(1.0 / 3600.0);
  const int n = 181;
  EllipsoidalDem dem =
      flat_ellipsoidal_dem(deg_to_rad(41.75) - (n - 1) * step, deg_to_rad(41.75), deg_to_rad(11.40),
                           deg_to_rad(11.40) + (n - 1) * step, n, n, 200.0);
  for (int r = 0; r < n; ++r) {
    for (int c = 0; c < n; ++c) {
      dem.height_m[static_cast<std::size_t>(r) * n + c] =
          static_cast<float>(200.0 + 100.0 * std::sin(r * 0.07) * std::cos(c * 0.05));
    }
  }
  const AcquisitionSimulation s = simulate(a, dem);
  std::printf("sentinel-1: window lines %d+%d, bins %d+%d of %d x %d\n", s.window.line0,
              s.window.lines, s.window.bin0, s.window.bins, a.grid.lines, a.grid.bins);
  EXPECT_EQ(s.sim.image.lines, s.window.lines);
  EXPECT_EQ(s.sim.image.bins, s.window.bins);
  EXPECT_GT(s.window.lines, 300);
  EXPECT_GT(s.window.bins, 700);
  std::size_t with_power = 0;
  for (std::size_t i = 0; i < s.sim.image.mean_power_w.size(); ++i) {
    with_power += s.sim.image.mean_power_w[i] > 0.0f;
  }
  EXPECT_GT(with_power, s.sim.image.mean_power_w.size() / 2);
}

}  // namespace
}  // namespace ris
