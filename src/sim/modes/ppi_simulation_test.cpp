// PPI: per-ray shadow of the predicted length, a ring of equal targets at
// equal radius, a symmetric scene's symmetric scope, thread independence and
// bad input (MODEL.md section 2, "PPI").
#include "ris/sim/ppi_simulation.h"

#include <fmt/format.h>

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "ris/image/greytone_terms.h"
#include "ris/scene/geo_frame.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"
#include "slar_stage_reference.h"

namespace ris {
namespace {

constexpr double kCell = 5.0;  // 200 x 200 cells: 1000 m square, SW corner (0, 0)
constexpr double kMast = 30.0;

RadarParams ppi_radar(const std::string& extra_scan = "", const std::string& site = "") {
  return radar_from_toml(toml::parse(R"(
mode = "ppi"
frequency = "9.41 GHz"
polarisation = "HH"
pulse_width = "0.05 us"
near_range = 0
far_range = "450 m"
azimuth_beamwidth = "2 deg"
transmit_power = "10 kW"
antenna_gain_db = 30
[site]
)" + (site.empty() ? std::string("position = [500.0, 500.0]\nheight = \"30 m\"\n") : site) +
                                     "[scan]\n" + extra_scan),
                         "ppi.toml");
}

Scene flat_scene() {
  return Scene::flat(200, 200, kCell, 0.0f, 0);
}

// The cell whose centre is nearest (x, y).
std::size_t cell_at(const Scene& s, double x, double y) {
  const auto [c, r] = s.grid_from_world(x, y);
  return s.index(static_cast<int>(r), static_cast<int>(c));
}

TEST(PpiSimulation, TowerCastsARadialShadowOfThePredictedLength) {
  // A 10 m tower 2 x 2 cells wide, 200-210 m north of a radar on a 30 m mast.
  Scene s = flat_scene();
  const double h_tower = 10.0;
  for (double x : {497.5, 502.5})
    for (double y : {702.5, 707.5}) s.elevation_m[cell_at(s, x, y)] = float(h_tower);
  const PpiSimulation sim = simulate_ppi(s, ppi_radar(), test::CosineSigma0Source());
  const PpiGeometry& g = sim.geometry;
  ASSERT_EQ(g.scan_rays, 360);
  // The shadow ends where the ray through the tower's top far edge (u_top =
  // 207.5 m, the last cell centre at full height) meets the ground:
  // u_end = u_top H / (H - h), a shadow u_top h / (H - h) long.
  const double u_top = 207.5;
  const double u_end = u_top * kMast / (kMast - h_tower);  // 311.25 m
  for (int ray : {g.pad + 0, g.pad + 359}) {               // rays centred at 0.5 and 359.5 deg
    int last_shadow = -1, first_shadow = -1;
    for (int j = 0; j < g.rays.samples; ++j) {
      if (g.rays.flags[g.rays.index(ray, j)] & sample_flag::kShadow) {
        if (first_shadow < 0) first_shadow = j;
        last_shadow = j;
      }
    }
    ASSERT_GE(last_shadow, 0) << "ray " << ray;
    EXPECT_NEAR(g.rays.sample_u_m(first_shadow), 210.0, kCell) << "ray " << ray;
    EXPECT_NEAR(g.rays.sample_u_m(last_shadow), u_end, kCell) << "ray " << ray;
    // Predicted length u_top h / (H - h) = 103.75 m, within a cell.
    EXPECT_NEAR(g.rays.sample_u_m(last_shadow) - u_top, u_top * h_tower / (kMast - h_tower), kCell);
  }
  // Rays well away from the tower (east, south, west) see no shadow.
  for (int deg : {90, 180, 270}) {
    for (int j = 0; j < g.rays.samples; ++j)
      ASSERT_FALSE(g.rays.flags[g.rays.index(g.pad + deg, j)] & sample_flag::kShadow) << deg;
  }
}

TEST(PpiSimulation, RingOfEqualTargetsAppearsAtEqualRadiusWithEqualPower) {
  const Scene s = flat_scene();
  SlarOptions opt;
  const double radius = 300.0;
  for (int i = 0; i < 12; ++i) {
    // On ray centres (30 i + 0.5 deg) so each target fills one ray's sector.
    const double a = deg_to_rad(30.0 * i + 0.5);
    PointTarget t;
    t.name = "t" + std::to_string(i);
    t.x_m = 500.0 + radius * std::sin(a);
    t.y_m = 500.0 + radius * std::cos(a);
    t.rcs_m2 = 100.0;
    t.index = i;
    opt.targets.push_back(t);
  }
  const RadarParams radar = ppi_radar();
  const PpiSimulation with = simulate_ppi(s, radar, test::CosineSigma0Source(), opt);
  const PpiSimulation without = simulate_ppi(s, radar, test::CosineSigma0Source());
  EXPECT_TRUE(with.hidden_targets.empty());
  const SlarImage& a = with.bscope;
  const SlarImage& b = without.bscope;
  const double R = std::hypot(radius, kMast);
  const int bin = static_cast<int>((R - a.range.near_m) / a.range.bin_m);
  // P = P_t G^2 lambda^2 sigma / ((4 pi)^3 R^4), uniform elevation pattern.
  const double expected = radar_equation_power_w(radar.transmit_power_w, 100.0, 1.0,
                                                 radar.peak_gain, radar.wavelength_m(), R);
  for (int i = 0; i < 12; ++i) {
    const int ray = 30 * i;
    // The target brightens its ray most at the same bin for all.
    const auto added_at = [&](int k) {
      return double(a.mean_power_w[a.index(ray, k)]) - b.mean_power_w[b.index(ray, k)];
    };
    int best = 0;
    for (int k = 1; k < a.bins; ++k)
      if (added_at(k) > added_at(best)) best = k;
    EXPECT_EQ(best, bin) << "target " << i;
    const double added =
        double(a.mean_power_w[a.index(ray, bin)]) - b.mean_power_w[b.index(ray, bin)];
    EXPECT_NEAR(added / expected, 1.0, 1e-3) << "target " << i;
  }
  // On the scope: every pixel the targets brighten lies at their radius.
  std::vector<float> diff(a.mean_power_w.size());
  for (std::size_t i = 0; i < diff.size(); ++i) diff[i] = a.mean_power_w[i] - b.mean_power_w[i];
  const std::vector<float> scope = to_ppi_scope(diff, with.scope_grid);
  const PpiScopeGrid& g = with.scope_grid;
  int at_radius = 0;
  for (int row = 0; row < g.size; ++row)
    for (int col = 0; col < g.size; ++col) {
      const float v = scope[static_cast<std::size_t>(row) * g.size + col];
      if (std::isfinite(v) && v > 0.5 * expected) {
        ++at_radius;
        EXPECT_NEAR(std::hypot(g.east_m(col), g.north_m(row)), R, a.range.bin_m + g.pixel_m);
      }
    }
  EXPECT_GE(at_radius, 12);
}

TEST(PpiSimulation, SymmetricSceneGivesASymmetricScope) {
  // Blocks mirrored about the north-south line through the radar (x = 500 m).
  Scene s = flat_scene();
  const auto block = [&](int r0, int c0, int n, float h, std::uint16_t cat) {
    for (int r = r0; r < r0 + n; ++r)
      for (int c = c0; c < c0 + n; ++c) {
        for (int cc : {c, 199 - c}) {
          s.elevation_m[s.index(r, cc)] = h;
          s.category[s.index(r, cc)] = cat;
        }
      }
  };
  block(40, 120, 10, 20.0f, 2);
  block(130, 150, 6, 8.0f, 3);
  block(90, 60, 4, 12.0f, 1);
  const PpiSimulation sim = simulate_ppi(s, ppi_radar(), test::CosineSigma0Source());
  const std::vector<float> scope = to_ppi_scope(sim.bscope.mean_power_w, sim.scope_grid);
  const int n = sim.scope_grid.size;
  ASSERT_EQ(n % 2, 0);
  double worst = 0.0;
  int compared = 0;
  for (int row = 0; row < n; ++row)
    for (int col = 0; col < n / 2; ++col) {
      const float l = scope[static_cast<std::size_t>(row) * n + col];
      const float r = scope[static_cast<std::size_t>(row) * n + (n - 1 - col)];
      ASSERT_EQ(std::isfinite(l), std::isfinite(r)) << row << "," << col;
      if (!std::isfinite(l) || (l == 0.0f && r == 0.0f)) continue;
      worst = std::max(worst, std::abs(double(l) - r) / std::max(double(l), double(r)));
      ++compared;
    }
  EXPECT_GT(compared, 1000);
  EXPECT_LT(worst, 1e-3);
}

TEST(PpiSimulation, SameSeedSameBytesForOneAndTwoThreads) {
  Scene s = flat_scene();
  for (int r = 50; r < 60; ++r)
    for (int c = 120; c < 130; ++c) s.elevation_m[s.index(r, c)] = 15.0f;
  const RadarParams radar = ppi_radar("range_rings = \"100 m\"\n");
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const PpiPictures a = render_ppi(simulate_ppi(s, radar, test::CosineSigma0Source()), 9);
  omp_set_num_threads(2);
  const PpiPictures b = render_ppi(simulate_ppi(s, radar, test::CosineSigma0Source()), 9);
  omp_set_num_threads(saved);
  EXPECT_EQ(a.scope_grey, b.scope_grey);
  EXPECT_EQ(a.bscope_grey, b.bscope_grey);
  ASSERT_EQ(a.speckled_power_w.size(), b.speckled_power_w.size());
  EXPECT_EQ(0, std::memcmp(a.speckled_power_w.data(), b.speckled_power_w.data(),
                           a.speckled_power_w.size() * sizeof(float)));
}

TEST(PpiSimulation, SectorScopeLeavesOutsideTheSectorEmpty) {
  const PpiSimulation sim =
      simulate_ppi(flat_scene(), ppi_radar("start = \"45 deg\"\nwidth = \"90 deg\"\n"),
                   test::CosineSigma0Source());
  EXPECT_EQ(sim.bscope.lines, 90);
  const PpiPictures pic = render_ppi(sim, 1);
  const PpiScopeGrid& g = sim.scope_grid;
  // North-west of the radar: outside; east: inside.
  const auto at = [&](double e, double nn) {
    const int col = static_cast<int>(std::floor(e / g.pixel_m + 0.5 * g.size));
    const int row = static_cast<int>(std::floor(0.5 * g.size - nn / g.pixel_m));
    return pic.scope_mask[static_cast<std::size_t>(row) * g.size + col];
  };
  EXPECT_TRUE(at(-200.0, 200.0) & pixel_flag::kNoData);
  EXPECT_FALSE(at(200.0, 0.0) & pixel_flag::kNoData);
}

// PPI goes through the line engine (the polar source, the rays' geometry
// kept, targets found lit or hidden ray by ray) with the stage path's bytes
// (tests/slar_stage_reference.h): the B-scope, the rays' geometry and
// counts, the point returns and their power, the hidden targets; full
// circle and a sector, 1 and 2 threads.
TEST(PpiSimulation, EngineEqualsStagesByteForByte) {
  Scene s = flat_scene();
  for (double x : {497.5, 502.5})
    for (double y : {702.5, 707.5}) s.elevation_m[cell_at(s, x, y)] = 20.0f;
  for (std::size_t i = 0; i < s.size(); i += 7) s.category[i] = 1;
  s.valid[cell_at(s, 300.0, 620.0)] = 0;
  std::vector<PointTarget> targets;
  int index = 0;
  for (const auto& [x, y] :
       {std::pair{500.0, 800.0}, std::pair{500.0, 650.0}, std::pair{800.0, 500.0},
        std::pair{300.0, 300.0}, std::pair{960.0, 960.0}, std::pair{501.0, 900.0}}) {
    PointTarget t;
    t.name = fmt::format("t{}", index);
    t.x_m = x;
    t.y_m = y;
    t.height_m = 1.0;
    t.rcs_m2 = 100.0;
    t.source_file = "targets.toml";
    t.index = index++;
    targets.push_back(t);
  }
  SlarOptions o;
  o.targets = targets;
  const test::CosineSigma0Source src;
  const int saved = omp_get_max_threads();
  std::size_t hidden = 0, seen = 0;
  for (const std::string& scan :
       {std::string(), std::string("start = \"-40 deg\"\nwidth = \"100 deg\"\n")}) {
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      const std::string what = fmt::format("scan '{}' threads {}", scan, threads);
      const PpiSimulation ref = test::simulate_ppi_by_stages(s, ppi_radar(scan), src, o);
      const PpiSimulation eng = simulate_ppi(s, ppi_radar(scan), src, o);
      using test::same_bytes;
      EXPECT_TRUE(same_bytes(ref.bscope.mean_power_w, eng.bscope.mean_power_w)) << what;
      EXPECT_TRUE(same_bytes(ref.bscope.area_m2, eng.bscope.area_m2)) << what;
      EXPECT_TRUE(same_bytes(ref.bscope.mask, eng.bscope.mask)) << what;
      EXPECT_TRUE(same_bytes(ref.bscope.mapped_count, eng.bscope.mapped_count)) << what;
      EXPECT_TRUE(same_bytes(ref.bscope.visible_count, eng.bscope.visible_count)) << what;
      EXPECT_TRUE(same_bytes(ref.bscope.point_power_w, eng.bscope.point_power_w)) << what;
      EXPECT_EQ(ref.bscope.samples_in_swath, eng.bscope.samples_in_swath) << what;
      const SlarGeometry &a = ref.geometry.rays, &b = eng.geometry.rays;
      EXPECT_TRUE(same_bytes(a.height_m, b.height_m)) << what;
      EXPECT_TRUE(same_bytes(a.slant_range_m, b.slant_range_m)) << what;
      EXPECT_TRUE(same_bytes(a.incidence_rad, b.incidence_rad)) << what;
      EXPECT_TRUE(same_bytes(a.local_incidence_rad, b.local_incidence_rad)) << what;
      EXPECT_TRUE(same_bytes(a.area_m2, b.area_m2)) << what;
      EXPECT_TRUE(same_bytes(a.range_near_end_m, b.range_near_end_m)) << what;
      EXPECT_TRUE(same_bytes(a.range_far_end_m, b.range_far_end_m)) << what;
      EXPECT_TRUE(same_bytes(a.category, b.category)) << what;
      EXPECT_TRUE(same_bytes(a.flags, b.flags)) << what;
      EXPECT_EQ(a.nodata_samples, b.nodata_samples) << what;
      EXPECT_EQ(a.shadow_samples, b.shadow_samples) << what;
      EXPECT_EQ(a.back_facing_samples, b.back_facing_samples) << what;
      EXPECT_EQ(a.layover_samples, b.layover_samples) << what;
      EXPECT_EQ(a.nodata_cells, b.nodata_cells) << what;
      EXPECT_EQ(ref.hidden_targets, eng.hidden_targets) << what;
      ASSERT_EQ(ref.point_returns.size(), eng.point_returns.size()) << what;
      for (std::size_t k = 0; k < ref.point_returns.size(); ++k) {
        EXPECT_EQ(ref.point_returns[k].line, eng.point_returns[k].line) << what << " " << k;
        EXPECT_EQ(ref.point_returns[k].along_m, eng.point_returns[k].along_m) << what << " " << k;
        EXPECT_EQ(ref.point_returns[k].slant_range_m, eng.point_returns[k].slant_range_m)
            << what << " " << k;
      }
      hidden += eng.hidden_targets.size();
      seen += eng.point_returns.size();
    }
  }
  omp_set_num_threads(saved);
  EXPECT_GT(hidden, 0u);  // behind the tower, outside the sector
  EXPECT_GT(seen, 0u);
}

TEST(PpiSimulation, BadSiteIsAnInputError) {
  const Scene s = flat_scene();
  try {
    simulate_ppi(s, ppi_radar("", "position = [1500.0, 500.0]\nheight = 30\n"),
                 test::CosineSigma0Source());
    ADD_FAILURE() << "site outside the scene accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "site.position");
    EXPECT_NE(std::string(e.what()).find("outside the scene"), std::string::npos) << e.what();
  }
  Scene hill = flat_scene();
  for (float& h : hill.elevation_m) h = 120.0f;
  try {
    simulate_ppi(hill, ppi_radar("", "position = [500.0, 500.0]\naltitude = 100\n"),
                 test::CosineSigma0Source());
    ADD_FAILURE() << "antenna below the terrain accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "site.altitude");
    EXPECT_NE(std::string(e.what()).find("below the terrain"), std::string::npos) << e.what();
  }
  SlarOptions opt;
  PointTarget t;
  t.name = "far away";
  t.x_m = 2000.0;
  t.y_m = 10.0;
  t.rcs_m2 = 10.0;
  t.source_file = "targets.toml";
  opt.targets.push_back(t);
  try {
    simulate_ppi(s, ppi_radar(), test::CosineSigma0Source(), opt);
    ADD_FAILURE() << "target off the scene accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "targets.toml");
    EXPECT_EQ(e.key(), "target[0].position");
    EXPECT_NE(std::string(e.what()).find("off the scene"), std::string::npos) << e.what();
  }
}

// 1.8 M rays: their geometry (31 bytes a sample) is refused by the memory
// check before it is allocated, naming the key (a run with an output folder
// meets the disk check first: tests/hardening_cli_test.cpp).
TEST(PpiSimulation, TooManyRaysAreRefusedBeforeTheirGeometryIsAllocated) {
  ::setenv("RIS_MAX_MEMORY_MB", "2048", 1);
  try {
    simulate_ppi(flat_scene(), ppi_radar("ray_spacing = \"2e-4 deg\"\n"),
                 test::CosineSigma0Source());
    ADD_FAILURE() << "1.8 M rays accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "scan.ray_spacing");
    EXPECT_NE(std::string(e.what()).find("rays x 180 samples needs"), std::string::npos)
        << e.what();
  }
  ::unsetenv("RIS_MAX_MEMORY_MB");
}

TEST(PpiSimulation, SiteInLatitudeLongitudeEqualsItsProjectedPosition) {
  // The flat scene placed in UTM zone 33N near Rome; the site given by the
  // latitude/longitude of the scene point (500, 500) gives the same B-scope.
  Scene s = flat_scene();
  s.crs_wkt = utm_wkt_for(12.5, 41.9);
  s.origin_x_m = 290000.0;
  s.origin_y_m = 4640000.0 + 200 * kCell;
  const double x = 290000.0 + 500.0, y = 4640000.0 + 500.0;
  const auto [lon, lat] = GeoFrame(s.crs_wkt, "test").lonlat_from_scene(x, y);
  const PpiSimulation by_xy =
      simulate_ppi(s, ppi_radar("", fmt::format("position = [{}, {}]\nheight = 30\n", x, y)),
                   test::CosineSigma0Source());
  const PpiSimulation by_latlon = simulate_ppi(
      s, ppi_radar("", fmt::format("latlon = [{:.12f}, {:.12f}]\nheight = 30\n", lat, lon)),
      test::CosineSigma0Source());
  EXPECT_NEAR(by_latlon.geometry.site_x_m, x, 0.01);
  EXPECT_NEAR(by_latlon.geometry.site_y_m, y, 0.01);
  ASSERT_EQ(by_xy.bscope.mean_power_w.size(), by_latlon.bscope.mean_power_w.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < by_xy.bscope.mean_power_w.size(); ++i) {
    const double a = by_xy.bscope.mean_power_w[i], b = by_latlon.bscope.mean_power_w[i];
    if (a > 0.0) worst = std::max(worst, std::abs(b - a) / a);
  }
  EXPECT_LT(worst, 1e-3);
  // Without a CRS a latitude/longitude site cannot be placed.
  try {
    simulate_ppi(flat_scene(), ppi_radar("", "latlon = [41.9, 12.5]\nheight = 30\n"),
                 test::CosineSigma0Source());
    ADD_FAILURE() << "latlon site on a scene without CRS accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.key(), "site.latlon");
    EXPECT_NE(std::string(e.what()).find("no CRS"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ris
