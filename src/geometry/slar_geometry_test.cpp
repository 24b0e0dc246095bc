#include "ris/geometry/slar_geometry.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

constexpr double kCell = 6.0;
constexpr double kH = 3000.0;
constexpr double kNear = 4000.0;  // ground distance from track to the near edge

// A right-looking track heading north; the scene's west edge is the near edge.
Track north_track(const Scene& s, double altitude_m = kH, double near_m = kNear) {
  TrackSpec spec;
  spec.heading_rad = 0.0;
  spec.near_edge_ground_m = near_m;
  spec.altitude_m = altitude_m;
  return resolve_track(spec, s, "radar.toml");
}

TEST(SlarGeometry, FlatPlaneSlantRangeIncidenceAreaAndNoFlags) {
  const Scene s = Scene::flat(20, 50, kCell, 10.0f, 3);
  const SlarGeometry g = compute_slar_geometry(s, north_track(s), 0.0, "radar.toml");
  ASSERT_TRUE(g.direct_sampling);
  EXPECT_EQ(g.lines, 20);
  EXPECT_EQ(g.samples, 50);
  EXPECT_DOUBLE_EQ(g.line_spacing_m, kCell);
  for (int line : {0, 7, 19}) {
    for (int j : {0, 25, 49}) {
      const std::size_t i = g.index(line, j);
      const double u = kNear + (j + 0.5) * kCell;  // cell centre
      EXPECT_NEAR(g.sample_u_m(j), u, 1e-9);
      const double D = kH - 10.0;
      EXPECT_NEAR(g.slant_range_m[i], std::hypot(u, D), 1e-3);
      EXPECT_NEAR(g.incidence_rad[i], std::atan2(u, D), 1e-6);
      EXPECT_NEAR(g.local_incidence_rad[i], std::atan2(u, D), 1e-4);
      EXPECT_NEAR(g.area_m2[i], kCell * kCell, 1e-4);
      EXPECT_NEAR(g.range_near_end_m[i], std::hypot(u - kCell / 2, D), 1e-3);
      EXPECT_NEAR(g.range_far_end_m[i], std::hypot(u + kCell / 2, D), 1e-3);
      EXPECT_EQ(g.flags[i], 0);
      EXPECT_EQ(g.category[i], 3);
    }
  }
  EXPECT_EQ(g.shadow_samples + g.layover_samples + g.back_facing_samples + g.nodata_samples, 0);
}

// z = (x - x_start) tan(45 deg): a slope rising away from a radar looking east.
TEST(SlarGeometry, FortyFiveDegreeSlopeFacingRadarHasLocalIncidenceThetaMinus45) {
  Scene s = Scene::flat(10, 60, kCell, 0.0f, 1);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c)
      s.elevation_m[s.index(r, c)] = static_cast<float>((c + 0.5) * kCell);
  const SlarGeometry g = compute_slar_geometry(s, north_track(s), 0.0, "radar.toml");
  for (int j = 1; j < s.cols - 1; ++j) {  // interior: central differences are exact
    const std::size_t i = g.index(5, j);
    const double theta = g.incidence_rad[i];
    EXPECT_NEAR(g.local_incidence_rad[i], theta - deg_to_rad(45.0), 1e-5) << j;
    EXPECT_NEAR(g.area_m2[i], kCell * kCell * std::sqrt(2.0), 1e-3);
  }
  EXPECT_EQ(g.back_facing_samples, 0);
}

// A box (wall) of height h across the track's whole length, from column c1
// to c2 - 1.
Scene box_scene(int c1, int c2, float h) {
  Scene s = Scene::flat(8, 200, kCell, 0.0f, 1);
  for (int r = 0; r < s.rows; ++r)
    for (int c = c1; c < c2; ++c) s.elevation_m[s.index(r, c)] = h;
  return s;
}

TEST(SlarGeometry, BoxShadowLengthIsHeightTimesTanThetaAtFarEdge) {
  const float h = 150.0f;
  const int c1 = 60, c2 = 80;
  const Scene s = box_scene(c1, c2, h);
  const SlarGeometry g = compute_slar_geometry(s, north_track(s), 0.0, "radar.toml");
  const double u_far_edge = kNear + c2 * kCell;
  const double expected = h * u_far_edge / (kH - h);  // h tan(theta) at the far top edge
  int shadowed = 0;
  for (int j = c2; j < s.cols; ++j)
    shadowed += (g.flags[g.index(3, j)] & sample_flag::kShadow) ? 1 : 0;
  EXPECT_NEAR(shadowed * kCell, expected, kCell);
  // Nothing in front of the box is shadowed; the shadow is one contiguous run.
  for (int j = 0; j < c2; ++j) EXPECT_FALSE(g.flags[g.index(3, j)] & sample_flag::kShadow) << j;
  for (int j = c2; j < c2 + shadowed; ++j)
    EXPECT_TRUE(g.flags[g.index(3, j)] & sample_flag::kShadow) << j;
}

TEST(SlarGeometry, BoxLayoverSpansFromTopNearEdgeToGroundAtSameRange) {
  const float h = 150.0f;
  const int c1 = 60, c2 = 80;
  const Scene s = box_scene(c1, c2, h);
  const SlarGeometry g = compute_slar_geometry(s, north_track(s), 0.0, "radar.toml");
  // SNAP zone: from the box's first top sample (R_top) up to the last ground
  // sample before it (the largest R seen before the box).
  const double u_top = g.sample_u_m(c1), u_ground = g.sample_u_m(c1 - 1);
  const double r_top = std::hypot(u_top, kH - h);
  const double r_ground = std::hypot(u_ground, kH);
  double r_min = 1e30, r_max = -1e30;
  int first = -1, last = -1;
  for (int j = 0; j < s.cols; ++j) {
    const std::size_t i = g.index(4, j);
    if (!(g.flags[i] & sample_flag::kLayover)) continue;
    r_min = std::min(r_min, double(g.slant_range_m[i]));
    r_max = std::max(r_max, double(g.slant_range_m[i]));
    if (first < 0) first = j;
    last = j;
  }
  EXPECT_NEAR(r_min, r_top, 0.01);
  EXPECT_NEAR(r_max, r_ground, 0.01);
  // Ground samples whose R exceeds R_top lie in layover, and top samples
  // nearer than the ground's R do.
  const int expected_first =
      static_cast<int>(std::ceil((std::sqrt(r_top * r_top - kH * kH) - kNear) / kCell - 0.5));
  EXPECT_EQ(first, expected_first);
  const int expected_last =
      static_cast<int>(
          std::ceil((std::sqrt(r_ground * r_ground - (kH - h) * (kH - h)) - kNear) / kCell - 0.5)) -
      1;
  EXPECT_EQ(last, expected_last);
}

TEST(SlarGeometry, TrackHeadingEastOnTransposedSceneGivesTheSameGeometry) {
  // Scene A: track north, looking east. Scene B: A rotated so that the track
  // heads east looking south; the direct sampler must see the same lines.
  Scene a = Scene::flat(12, 30, kCell, 0.0f, 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    a.elevation_m[i] = static_cast<float>(20.0 * std::sin(0.37 * double(i)));
  Scene b = Scene::flat(30, 12, kCell, 0.0f, 1);
  // A's row r (north first) is B's column (track start = west first), A's
  // column c (east, growing u) is B's row (south, growing u): B(r', c') with
  // c' = rows_a - 1 - r, r' = c.
  for (int r = 0; r < a.rows; ++r)
    for (int c = 0; c < a.cols; ++c)
      b.elevation_m[b.index(c, a.rows - 1 - r)] = a.elevation_m[a.index(r, c)];
  TrackSpec spec;
  spec.heading_rad = kPi / 2;
  spec.near_edge_ground_m = kNear;
  spec.altitude_m = kH;
  const Track tb = resolve_track(spec, b, "radar.toml");
  const SlarGeometry ga = compute_slar_geometry(a, north_track(a), 0.0, "radar.toml");
  const SlarGeometry gb = compute_slar_geometry(b, tb, 0.0, "radar.toml");
  ASSERT_TRUE(gb.direct_sampling);
  ASSERT_EQ(ga.lines, gb.lines);
  ASSERT_EQ(ga.samples, gb.samples);
  for (std::size_t i = 0; i < ga.flags.size(); ++i) {
    EXPECT_NEAR(ga.slant_range_m[i], gb.slant_range_m[i], 1e-3);
    EXPECT_NEAR(ga.local_incidence_rad[i], gb.local_incidence_rad[i], 1e-5);
    EXPECT_EQ(ga.flags[i], gb.flags[i]);
  }
}

TEST(SlarGeometry, TrackHeadingSouthOnSceneTurnedHalfwayGivesTheSameGeometry) {
  // Scene C is A turned by 180 deg; a track heading south looks west at it.
  Scene a = Scene::flat(12, 30, kCell, 0.0f, 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    a.elevation_m[i] = static_cast<float>(30.0 * std::cos(0.23 * double(i)));
  Scene c = a;
  for (int r = 0; r < a.rows; ++r)
    for (int col = 0; col < a.cols; ++col)
      c.elevation_m[c.index(a.rows - 1 - r, a.cols - 1 - col)] = a.elevation_m[a.index(r, col)];
  TrackSpec spec;
  spec.heading_rad = kPi;
  spec.near_edge_ground_m = kNear;
  spec.altitude_m = kH;
  const SlarGeometry ga = compute_slar_geometry(a, north_track(a), 0.0, "radar.toml");
  const SlarGeometry gc =
      compute_slar_geometry(c, resolve_track(spec, c, "radar.toml"), 0.0, "radar.toml");
  ASSERT_TRUE(gc.direct_sampling);
  ASSERT_EQ(ga.flags.size(), gc.flags.size());
  for (std::size_t i = 0; i < ga.flags.size(); ++i) {
    EXPECT_NEAR(ga.slant_range_m[i], gc.slant_range_m[i], 1e-3);
    EXPECT_NEAR(ga.local_incidence_rad[i], gc.local_incidence_rad[i], 1e-5);
    EXPECT_EQ(ga.flags[i], gc.flags[i]);
  }
}

TEST(SlarGeometry, LeftLookingTrackOnMirroredSceneGivesTheSameGeometry) {
  Scene a = Scene::flat(12, 30, kCell, 0.0f, 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    a.elevation_m[i] = static_cast<float>(25.0 * std::sin(0.71 * double(i)));
  Scene m = a;
  for (int r = 0; r < a.rows; ++r)
    for (int col = 0; col < a.cols; ++col)
      m.elevation_m[m.index(r, a.cols - 1 - col)] = a.elevation_m[a.index(r, col)];
  TrackSpec spec;
  spec.heading_rad = 0.0;
  spec.look_side = LookSide::left;
  spec.near_edge_ground_m = kNear;
  spec.altitude_m = kH;
  const SlarGeometry ga = compute_slar_geometry(a, north_track(a), 0.0, "radar.toml");
  const SlarGeometry gm =
      compute_slar_geometry(m, resolve_track(spec, m, "radar.toml"), 0.0, "radar.toml");
  ASSERT_EQ(ga.flags.size(), gm.flags.size());
  for (std::size_t i = 0; i < ga.flags.size(); ++i) {
    EXPECT_NEAR(ga.slant_range_m[i], gm.slant_range_m[i], 1e-3);
    EXPECT_NEAR(ga.local_incidence_rad[i], gm.local_incidence_rad[i], 1e-5);
    EXPECT_EQ(ga.flags[i], gm.flags[i]);
  }
}

TEST(SlarGeometry, RotatedTrackUsesBilinearSamplingAtHalfCellSteps) {
  const Scene s = Scene::flat(40, 40, kCell, 5.0f, 2);
  TrackSpec spec;
  spec.heading_rad = deg_to_rad(30.0);
  spec.near_edge_ground_m = kNear;
  spec.altitude_m = kH;
  const Track t = resolve_track(spec, s, "radar.toml");
  const SlarGeometry g = compute_slar_geometry(s, t, 0.0, "radar.toml");
  EXPECT_FALSE(g.direct_sampling);
  EXPECT_LE(g.sample_step_m, 0.5 * kCell + 1e-12);
  // Every sample inside the scene carries the flat plane's geometry.
  int inside = 0;
  for (int line = 0; line < g.lines; ++line) {
    for (int j = 0; j < g.samples; ++j) {
      const std::size_t i = g.index(line, j);
      if (g.flags[i] & sample_flag::kUnseen) continue;
      ++inside;
      const double u = g.sample_u_m(j);
      EXPECT_NEAR(g.slant_range_m[i], std::hypot(u, kH - 5.0), 1e-2);
      EXPECT_NEAR(g.area_m2[i], g.line_spacing_m * g.sample_step_m, 1e-4);
      ASSERT_EQ(g.flags[i], 0);
    }
  }
  // Samples cover the scene's area (each stands for line_spacing x step).
  EXPECT_NEAR(inside * g.line_spacing_m * g.sample_step_m, 40 * 40 * kCell * kCell,
              0.03 * 40 * 40 * kCell * kCell);
}

TEST(SlarGeometry, TerrainAtOrAboveTheSensorIsAnInputError) {
  Scene s = Scene::flat(5, 5, kCell, 0.0f, 1);
  s.elevation_m[s.index(2, 3)] = static_cast<float>(kH);
  try {
    (void)compute_slar_geometry(s, north_track(s), 0.0, "radar.toml");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "radar.toml");
    EXPECT_EQ(e.key(), "track.altitude");
    EXPECT_NE(std::string(e.what()).find("row 2, column 3"), std::string::npos) << e.what();
  }
}

// The check compares each height with the altitude as a double: a cell one
// float below an altitude that is not a float passes, the float just above
// it does not (the scan's float threshold is exact), wherever the cell is
// (the vector blocks and the scalar rest), and a cell without data never
// counts.
TEST(SlarGeometry, TerrainCheckIsExactAtAnAltitudeBetweenTwoFloats) {
  // 3000.0001 rounds down to the float 3000, 2999.9999 up to it.
  for (const double altitude : {3000.0001, 2999.9999}) {
    const float f = static_cast<float>(altitude);
    const float above = double(f) >= altitude ? f : std::nextafter(f, 1e9f);
    const float below = std::nextafter(above, 0.0f);
    ASSERT_LT(double(below), altitude);
    ASSERT_GT(double(above), altitude);
    for (const std::size_t at : {0, 7, 8, 30, 35}) {
      Scene s = Scene::flat(6, 6, kCell, 0.0f, 1);
      s.elevation_m[at] = below;
      EXPECT_NO_THROW(check_terrain_below_sensor(s, altitude, "radar.toml")) << at;
      s.elevation_m[at] = above;
      EXPECT_THROW(check_terrain_below_sensor(s, altitude, "radar.toml"), InputError) << at;
      s.valid[at] = 0;
      EXPECT_NO_THROW(check_terrain_below_sensor(s, altitude, "radar.toml")) << at;
    }
  }
}

TEST(SlarGeometry, NoDataCellsAreCountedAndMaskedAndCastNoShadow) {
  Scene s = Scene::flat(6, 30, kCell, 0.0f, 1);
  int nans = 0;
  for (int r = 1; r < 4; ++r) {
    for (int c = 10; c < 14; ++c) {
      s.elevation_m[s.index(r, c)] = std::numeric_limits<float>::quiet_NaN();
      s.valid[s.index(r, c)] = 0;
      ++nans;
    }
  }
  const SlarGeometry g = compute_slar_geometry(s, north_track(s), 0.0, "radar.toml");
  EXPECT_EQ(g.nodata_cells, nans);
  EXPECT_EQ(g.nodata_samples, nans);
  EXPECT_EQ(g.shadow_samples, 0);
  // Rows 1..3 are lines 4..2 (the track starts at the south edge).
  const int line = s.rows - 1 - 2;
  EXPECT_EQ(g.flags[g.index(line, 11)], sample_flag::kNoData);
  EXPECT_TRUE(std::isnan(g.slant_range_m[g.index(line, 11)]));
  EXPECT_EQ(g.flags[g.index(line, 14)], 0);
}

}  // namespace
}  // namespace ris
