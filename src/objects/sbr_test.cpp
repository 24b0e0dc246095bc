// The SBR tracer against closed-form radar cross sections (PEC).
//
// Error budget (each case): the PO-SBR answer differs from the closed form
// by (1) the ray grid's discretisation of the aperture edges (rays of
// spacing lambda/10 over apertures of >= 10 lambda: < 0.1 dB); (2) PO's own
// edge terms, absent from the closed forms, which are PO results themselves
// (plate, dihedral, trihedral: 0); (3) for sphere and cylinder, the
// faceting (facets well inside the first Fresnel zone: < 0.3 dB) and the
// optics limit (ka >= 30: the creeping wave's ~ 1/(ka) ripple < 0.3 dB).
// Tolerance 0.5 dB unless stated.
#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "ris/objects/mesh.h"
#include "ris/objects/sbr.h"
#include "ris/util/units.h"

namespace ris {
namespace {

constexpr double kF = 10e9;
const double kLambda = kSpeedOfLight_m_per_s / kF;

double db(double x) {
  return 10.0 * std::log10(x);
}

SbrResult trace(const TriangleMesh& m, double az = 0.0, double el = 0.0, int bounces = 3) {
  EmbreeScene scene(m);
  SbrOptions o;
  o.max_bounces = bounces;
  return trace_sbr(scene, {pec_surface()}, kF, radar_direction(az, el), o);
}

TEST(SbrClosedForm, SquarePlateNormalIncidence) {
  const double a = 0.3;
  const SbrResult r = trace(make_plate(a));
  const double expected = 4.0 * kPi * std::pow(a, 4) / (kLambda * kLambda);
  EXPECT_NEAR(db(r.rcs_m2[0]), db(expected), 0.5);
  EXPECT_NEAR(db(r.rcs_m2[3]), db(expected), 0.5);
  EXPECT_LT(r.rcs_m2[1], 1e-6 * expected);
}

TEST(SbrClosedForm, DielectricPlateScalesByFresnelPower) {
  // PO of a dielectric plate at normal incidence: |Gamma|^2 4 pi a^4 / lambda^2,
  // Gamma = (1 - sqrt(eps)) / (1 + sqrt(eps)); needs both J and M.
  const double a = 0.3;
  const std::complex<double> eps{5.24, -0.56};
  EmbreeScene scene(make_plate(a));
  SurfaceResponse glassy;
  glassy.pec = false;
  glassy.eps = eps;
  const SbrResult r = trace_sbr(scene, {glassy}, kF, radar_direction(0, 0), {});
  const double gamma2 = std::norm((1.0 - std::sqrt(eps)) / (1.0 + std::sqrt(eps)));
  const double expected = gamma2 * 4.0 * kPi * std::pow(a, 4) / (kLambda * kLambda);
  EXPECT_NEAR(db(r.rcs_m2[0]), db(expected), 0.5);
  EXPECT_NEAR(db(r.rcs_m2[3]), db(expected), 0.5);
}

TEST(SbrClosedForm, SquarePlatePatternFollowsSincSquared) {
  // PO: sigma = 4 pi a^4 / lambda^2 cos^2(t) sinc^2(k a sin t) (Ruck et al.
  // 1970, Radar Cross Section Handbook, 7.2), over the main lobe and the
  // first two sidelobes. In dB within 10 dB of the peak; everywhere as an
  // amplitude error below 3% of the peak's amplitude (the grid's edge rays:
  // one tube of 100 across the plate is 1%, larger near the nulls in dB).
  const double a = 0.3, k = 2.0 * kPi / kLambda;
  const double peak = 4.0 * kPi * std::pow(a, 4) / (kLambda * kLambda);
  int compared = 0;
  for (double deg = 0.0; deg <= 8.0; deg += 0.25) {
    const double t = deg_to_rad(deg), x = k * a * std::sin(t);
    const double expected = peak * std::pow(std::cos(t) * (x == 0.0 ? 1.0 : std::sin(x) / x), 2);
    const SbrResult r = trace(make_plate(a), t);
    for (int q : {0, 3}) {
      EXPECT_NEAR(std::sqrt(r.rcs_m2[q]), std::sqrt(expected), 0.03 * std::sqrt(peak))
          << deg << " deg, " << (q == 0 ? "HH" : "VV");
      if (expected < 0.1 * peak) continue;
      EXPECT_NEAR(db(r.rcs_m2[q]), db(expected), 0.5) << deg << " deg, " << (q == 0 ? "HH" : "VV");
      ++compared;
    }
  }
  EXPECT_GE(compared, 8);
}

TEST(SbrClosedForm, DihedralBoresight) {
  const double a = 0.3, b = 0.25;
  const SbrResult r = trace(make_dihedral(a, b));
  const double expected = 8.0 * kPi * a * a * b * b / (kLambda * kLambda);
  EXPECT_NEAR(db(r.rcs_m2[0]), db(expected), 0.5);
  EXPECT_NEAR(db(r.rcs_m2[3]), db(expected), 0.5);
  // Even bounce: HH and VV 180 degrees apart (backscatter alignment).
  const double phase = std::arg(r.s[0] / r.s[3]);
  EXPECT_NEAR(std::abs(phase), kPi, deg_to_rad(5.0));
}

TEST(SbrClosedForm, DihedralRolledAboutLineOfSightGivesTanSquaredTwoPhi) {
  for (double deg : {10.0, 15.0, 30.0}) {
    TriangleMesh m = make_dihedral(0.3, 0.25);
    place(m, {.roll_rad = deg_to_rad(deg)});
    const SbrResult r = trace(m);
    const double ratio = r.rcs_m2[1] / r.rcs_m2[0];
    EXPECT_NEAR(db(ratio), db(std::pow(std::tan(2.0 * deg_to_rad(deg)), 2)), 0.5) << deg;
    EXPECT_NEAR(std::abs(r.s[1] - r.s[2]), 0.0, 1e-3 * std::abs(r.s[1])) << "HV = VH, " << deg;
  }
}

TEST(SbrClosedForm, SquareTrihedralBoresight) {
  const double a = 0.2;
  const SbrResult r = trace(make_trihedral_square(a));
  const double expected = 12.0 * kPi * std::pow(a, 4) / (kLambda * kLambda);
  EXPECT_NEAR(db(r.rcs_m2[0]), db(expected), 0.5);
  EXPECT_NEAR(db(r.rcs_m2[3]), db(expected), 0.5);
  EXPECT_NEAR(std::arg(r.s[0] / r.s[3]), 0.0, deg_to_rad(5.0));  // odd bounce: in phase
}

TEST(SbrClosedForm, TriangularTrihedralBoresight) {
  const double a = 0.3;
  const SbrResult r = trace(make_trihedral_triangular(a));
  const double expected = 4.0 * kPi * std::pow(a, 4) / (3.0 * kLambda * kLambda);
  EXPECT_NEAR(db(r.rcs_m2[0]), db(expected), 0.5);
  EXPECT_NEAR(db(r.rcs_m2[3]), db(expected), 0.5);
  EXPECT_NEAR(std::arg(r.s[0] / r.s[3]), 0.0, deg_to_rad(5.0));
  EXPECT_LT(r.rcs_m2[1], 1e-3 * expected);
}

TEST(SbrClosedForm, SphereOpticsRegion) {
  const double radius = 0.3;  // ka = 63
  const SbrResult r = trace(make_sphere(radius, 6), 0.2, 0.3);
  EXPECT_NEAR(db(r.rcs_m2[0]), db(kPi * radius * radius), 0.5);
  EXPECT_NEAR(db(r.rcs_m2[3]), db(kPi * radius * radius), 0.5);
}

TEST(SbrClosedForm, CylinderBroadside) {
  const double radius = 0.15, length = 0.3;
  const SbrResult r = trace(make_cylinder(radius, length, 1440));
  const double expected = 2.0 * kPi * radius * length * length / kLambda;
  EXPECT_NEAR(db(r.rcs_m2[0]), db(expected), 0.5);
  EXPECT_NEAR(db(r.rcs_m2[3]), db(expected), 0.5);
}

TEST(SbrTracer, KeepsReturnsWithBounceCountAndPath) {
  EmbreeScene scene(make_dihedral(0.3, 0.25));
  SbrOptions o;
  o.keep_returns = true;
  const SbrResult r = trace_sbr(scene, {pec_surface()}, kF, radar_direction(0, 0), o);
  ASSERT_FALSE(r.returns.empty());
  int doubles = 0;
  for (const SbrReturn& ret : r.returns) {
    if (ret.bounces != 2) continue;
    ++doubles;
    // Two-way path of the fold: every double-bounce path equals 2 x (fold to origin) = 0.
    EXPECT_NEAR(ret.path_m, 0.0, 1e-4);
  }
  EXPECT_GT(doubles, 100);
  EXPECT_GT(r.rays_traced, r.rays_launched);
}

}  // namespace
}  // namespace ris
