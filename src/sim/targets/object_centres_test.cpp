// Scene objects in the image (ris/sim/object_centres.h, issue 32): a
// trihedral given as a mesh against the same reflector as a point target of
// its physical-optics RCS; a wall's double bounce at the wall's foot; the
// painted building's shadow; determinism over threads; refusals.
//
// Error budget: the SBR trihedral is within 0.1 dB of 12 pi a^4 / lambda^2
// at boresight (sbr_test.cpp); the image adds the point-target path both
// runs share, so mesh and point agree within 0.3 dB. Positions: a range bin
// (1 m) for the double bounce; the shadow within one cell (2 m) either way
// plus the sample step.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>
#include "ris/geometry/line_scan.h"
#include "ris/scene/scene_builder.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/object_centres.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

constexpr double kH = 3000.0;     // altitude
constexpr double kNear = 3000.0;  // track to the scene's west edge
constexpr double kCell = 2.0;

RadarParams sar(const std::string& pol = "HH", const std::string& mode = "sar") {
  std::string t = "mode = \"" + mode + "\"\nfrequency = \"9.6 GHz\"\npolarisation = \"" + pol +
                  R"("
near_range = "4000 m"
far_range = "4800 m"
range_bin = "1 m"
transmit_power = "1 kW"
antenna_gain_db = 30
[sar]
range_resolution = "1 m"
azimuth_resolution = "2 m"
coherent = false
[track]
altitude = "3000 m"
heading = "0 deg"
look_side = "right"
near_edge_distance = "3000 m"
)";
  return radar_from_toml(toml::parse(t), "sar.toml");
}

struct Loaded {
  Scene scene;
  std::vector<CulturalObject> objects;
};

Loaded load(const std::string& objects_toml) {
  const std::string text = R"(
[grid]
rows = 100
cols = 300
cell_size = 2.0
base_category = 1
)" + objects_toml;
  const SceneDescription d = parse_scene_description(toml::parse(text), "town.toml");
  return {build_scene(d), cultural_objects(d)};
}

SlarSimulation run(const Scene& s, const std::vector<PointTarget>& targets,
                   bool keep_geometry = false) {
  SlarOptions o;
  o.targets = targets;
  o.keep_geometry = keep_geometry;
  return simulate_slar(s, sar(), test::CosineSigma0Source(), o);
}

// Power above the scene's own in lines [l0, l1) x bins [b0, b1).
double excess_power_w(const SlarSimulation& with, const SlarSimulation& without, int l0, int l1,
                      int b0, int b1) {
  double sum = 0.0;
  for (int l = l0; l < l1; ++l) {
    for (int b = b0; b < b1; ++b) {
      const std::size_t i = with.image.index(l, b);
      sum += double(with.image.mean_power_w[i]) - double(without.image.mean_power_w[i]);
    }
  }
  return sum;
}

TEST(ObjectCentres, TrihedralMeshImagesAsItsPointTarget) {
  // A 1 m square trihedral at x = 300 m (u = 3300 m), its boresight on the
  // radar: azimuth 180 deg (the radar is west), tilted up by atan(H / u).
  const double u = kNear + 300.0;
  const double tilt_deg = rad_to_deg(std::atan2(kH, u));
  const Loaded l = load(fmt::format(R"(
[[object]]
type = "reflector"
shape = "trihedral"
x = 300.0
y = 101.0
size = 1.0
azimuth = 180
tilt = {}
)",
                                    tilt_deg));
  ObjectCentreStats st;
  const std::vector<PointTarget> c = object_scattering_centres(l.objects, l.scene, sar(), &st);
  ASSERT_EQ(c.size(), 1u);
  const double lambda = kSpeedOfLight_m_per_s / 9.6e9;
  const double sigma = 12.0 * kPi / (lambda * lambda);  // 12 pi a^4 / lambda^2, a = 1 m
  EXPECT_NEAR(10.0 * std::log10(c[0].rcs_m2 / sigma), 0.0, 0.2);
  EXPECT_NEAR(10.0 * std::log10(st.rcs_m2[0] / sigma), 0.0, 0.2);

  PointTarget p;
  p.name = "analytic";
  p.x_m = 300.0;
  p.y_m = 101.0;
  p.rcs_m2 = sigma;
  const SlarSimulation bare = run(l.scene, {});
  const SlarSimulation mesh = run(l.scene, c);
  const SlarSimulation point = run(l.scene, {p});
  ASSERT_EQ(mesh.point_returns.size(), 1u);
  ASSERT_EQ(point.point_returns.size(), 1u);
  // The centre sits where the apex is: the same line and range bin.
  EXPECT_EQ(mesh.point_returns[0].line, point.point_returns[0].line);
  EXPECT_NEAR(mesh.point_returns[0].slant_range_m, point.point_returns[0].slant_range_m, 0.5);
  const int line = point.point_returns[0].line;
  const int bin = static_cast<int>((point.point_returns[0].slant_range_m - 4000.0) / 1.0);
  const double e_mesh = excess_power_w(mesh, bare, line - 5, line + 6, bin - 8, bin + 9);
  const double e_point = excess_power_w(point, bare, line - 5, line + 6, bin - 8, bin + 9);
  ASSERT_GT(e_point, 0.0);
  EXPECT_NEAR(10.0 * std::log10(e_mesh / e_point), 0.0, 0.3);
}

// A 20 m x 30 m building 15 m high, its west wall facing the radar.
constexpr const char* kBuilding = R"(
[[object]]
type = "building"
footprint = [[200, 70], [230, 70], [230, 130], [200, 130]]
height = 15
category = 2
)";

TEST(ObjectCentres, WallGroundDoubleBounceImagesAtTheWallFoot) {
  const Loaded l = load(kBuilding);
  ObjectCentreStats st;
  const std::vector<PointTarget> c = object_scattering_centres(l.objects, l.scene, sar(), &st);
  ASSERT_FALSE(c.empty());
  // The strongest centres are the double bounce: at the wall's foot, where
  // a ray from the radar to the foot has the path of every wall-ground path.
  const double foot_range = std::hypot(kNear + 200.0, kH);
  double strongest = 0.0, at_foot = 0.0;
  for (const PointTarget& t : c) {
    strongest = std::max(strongest, t.rcs_m2);
    const double h = terrain_height_at(l.scene, t.x_m, t.y_m) + t.height_m;
    const double r = std::hypot(kNear + t.x_m, kH - h);
    if (std::abs(r - foot_range) <= 1.0) at_foot += t.rcs_m2;
  }
  double total = 0.0;
  for (const PointTarget& t : c) total += t.rcs_m2;
  EXPECT_GT(at_foot, 0.9 * total) << "the double bounce dominates and lies at the foot";

  const SlarSimulation bare = run(l.scene, {});
  const SlarSimulation with = run(l.scene, c);
  // In the image: along the wall's lines (y 70-130 m: lines 35-64), the
  // brightest excess is in the foot's range bin (+-1).
  const int foot_bin = static_cast<int>(std::floor(foot_range - 4000.0));
  for (int line = 40; line < 60; line += 5) {
    int best = -1;
    double best_w = 0.0;
    for (int b = 0; b < with.image.bins; ++b) {
      const std::size_t i = with.image.index(line, b);
      const double e = double(with.image.mean_power_w[i]) - double(bare.image.mean_power_w[i]);
      if (e > best_w) {
        best_w = e;
        best = b;
      }
    }
    EXPECT_NEAR(best, foot_bin, 1) << "line " << line;
  }
}

TEST(ObjectCentres, PaintedBuildingCastsItsShadow) {
  // Behind the building (east), the ground is in shadow for h tan(theta)
  // measured from the roof's far edge, theta the incidence there.
  const Loaded l = load(kBuilding);
  const SlarSimulation s = run(l.scene, {}, true);
  const SlarGeometry& g = s.geometry;
  ASSERT_FALSE(g.flags.empty());
  const int line = 50;
  const double u_edge = kNear + 230.0;
  const double expected = 15.0 * u_edge / (kH - 15.0);  // h tan(theta)
  double shadow = 0.0;
  for (int k = 0; k < g.samples; ++k) {
    const double u = g.sample_u_m(k);
    if (u > u_edge && (g.flags[g.index(line, k)] & sample_flag::kShadow)) shadow += g.sample_step_m;
  }
  EXPECT_NEAR(shadow, expected, kCell + g.sample_step_m);
}

TEST(ObjectCentres, SameCentresForAnyThreadCount) {
  const Loaded l = load(kBuilding);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const std::vector<PointTarget> one = object_scattering_centres(l.objects, l.scene, sar());
  omp_set_num_threads(2);
  const std::vector<PointTarget> two = object_scattering_centres(l.objects, l.scene, sar());
  omp_set_num_threads(saved);
  ASSERT_EQ(one.size(), two.size());
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].x_m, two[i].x_m);
    EXPECT_EQ(one[i].y_m, two[i].y_m);
    EXPECT_EQ(one[i].height_m, two[i].height_m);
    EXPECT_EQ(one[i].rcs_m2, two[i].rcs_m2);
  }
}

TEST(ObjectCentres, PolarisationsFollowTheScatteringMatrix) {
  // A dihedral tilted onto the radar (its fold then along the radar's V),
  // unrolled: HH and VV strong, HV and VH at least 30 dB below (reflection
  // symmetry); rolled by 22.5 deg, HV / HH = tan^2(2 phi) = 1 (sbr_test.cpp
  // checks the law at other angles).
  const double tilt_deg = rad_to_deg(std::atan2(kH, kNear + 300.0));
  const std::string dihedral = fmt::format(R"(
[[object]]
type = "reflector"
shape = "dihedral"
x = 300.0
y = 101.0
size = 1.0
azimuth = 180
tilt = {}
)",
                                           tilt_deg);
  const Loaded l = load(dihedral);
  ObjectCentreStats hh, hv, vh;
  object_scattering_centres(l.objects, l.scene, sar("HH"), &hh);
  object_scattering_centres(l.objects, l.scene, sar("HV"), &hv);
  object_scattering_centres(l.objects, l.scene, sar("VH"), &vh);
  EXPECT_LT(hv.rcs_m2[0], 1e-3 * hh.rcs_m2[0]);
  EXPECT_LT(vh.rcs_m2[0], 1e-3 * hh.rcs_m2[0]);
  const double lambda = kSpeedOfLight_m_per_s / 9.6e9;
  EXPECT_NEAR(10.0 * std::log10(hh.rcs_m2[0] / (8.0 * kPi / (lambda * lambda))), 0.0, 0.5);

  const Loaded rolled = load(dihedral + "roll = 22.5\n");
  object_scattering_centres(rolled.objects, rolled.scene, sar("HH"), &hh);
  object_scattering_centres(rolled.objects, rolled.scene, sar("HV"), &hv);
  EXPECT_NEAR(10.0 * std::log10(hv.rcs_m2[0] / hh.rcs_m2[0]), 0.0, 0.5);
}

void expect_refused(const std::string& objects, const std::string& key_word,
                    const RadarParams& radar = sar()) {
  try {
    const Loaded l = load(objects);
    object_scattering_centres(l.objects, l.scene, radar);
    ADD_FAILURE() << "accepted: " << objects;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(key_word), std::string::npos) << e.what();
  }
}

TEST(ObjectCentres, ObjectsOffTheGridAreSkippedAsEverySolid) {
  // The builder warns of an object wholly outside the grid and skips it
  // (docs/scene-format.md, "The composition rule"); it is not traced.
  const Loaded l = load(R"(
[[object]]
type = "reflector"
shape = "trihedral"
x = 300.0
y = 300.0
size = 1.0
)");
  EXPECT_TRUE(l.objects.empty());
}

TEST(ObjectCentres, BadObjectsAreRefusedByKey) {
  expect_refused(R"(
[[object]]
type = "building"
footprint = [[0, 0], [10, 10], [10, 0], [0, 10]]
height = 10
category = 2
)",
                 "crosses itself");
  expect_refused(R"(
[[object]]
type = "building"
footprint = [[0, 0], [10, 0]]
height = 10
category = 2
)",
                 "at least 3");
  expect_refused(R"(
[[object]]
type = "building"
footprint = [[0, 0], [10, 0], [10, 10]]
height = 10
roof = "gabled"
category = 2
)",
                 "roof");
  expect_refused(R"(
[[object]]
type = "building"
footprint = [[0, 0], [10, 0], [10, 10]]
height = 10
wall_material = "marble"
category = 2
)",
                 "wall_material");
  expect_refused(R"(
[[object]]
type = "reflector"
shape = "pentahedral"
x = 30.0
y = 30.0
size = 1.0
)",
                 "shape");
}

}  // namespace
}  // namespace ris
