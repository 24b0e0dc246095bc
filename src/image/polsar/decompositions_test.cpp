#include "ris/image/polsar/decompositions.h"

#include <gtest/gtest.h>

#include <cmath>

#include "ris/backscatter/category_covariance.h"
#include "ris/backscatter/library.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

constexpr double kDeg = 57.295779513082320877;

Hermitian3 t3_of(const Sinclair& s) {
  return outer(pauli_vector(s));
}

Hermitian3 dipole_volume_c3(double fv) {
  Hermitian3 c;
  c(0, 0) = c(2, 2) = fv;
  c(1, 1) = 2.0 * fv / 3.0;
  c(0, 2) = c(2, 0) = fv / 3.0;
  return c;
}

// Freeman & Durden's surface (beta) and double-bounce (alpha) C3s.
Hermitian3 surface_c3(double fs, Complex beta) {
  Hermitian3 c;
  c(0, 0) = fs * std::norm(beta);
  c(2, 2) = fs;
  c(0, 2) = fs * beta;
  c(2, 0) = std::conj(c(0, 2));
  return c;
}
Hermitian3 dihedral_c3(double fd, Complex alpha) {
  return surface_c3(fd, alpha);
}

TEST(CloudePottier, CanonicalTargets) {
  // A trihedral (odd bounce, S = I): alpha 0, H 0.
  const CloudePottier tri = cloude_pottier(t3_of({1.0, 0.0, 0.0, 1.0}));
  EXPECT_NEAR(tri.alpha_rad * kDeg, 0.0, 1e-6);
  EXPECT_NEAR(tri.entropy, 0.0, 1e-9);
  // A dihedral (S = diag(1, -1)): alpha 90.
  EXPECT_NEAR(cloude_pottier(t3_of({1.0, 0.0, 0.0, -1.0})).alpha_rad * kDeg, 90.0, 1e-6);
  // A dihedral turned by 45 deg: S = [0 1; 1 0], all of it HV (T33), alpha 90.
  const Hermitian3 rot = t3_of({0.0, 1.0, 1.0, 0.0});
  EXPECT_NEAR(rot(2, 2).real(), rot.trace(), 1e-15);
  EXPECT_NEAR(c3_from_t3(rot)(1, 1).real(), rot.trace(), 1e-15);  // pure C22 = 2|HV|^2
  EXPECT_NEAR(cloude_pottier(rot).alpha_rad * kDeg, 90.0, 1e-6);
}

TEST(CloudePottier, RandomDipoleVolume) {
  // T3 of the dipole cloud: eigenvalues (4/3, 2/3, 2/3) fv, so p = (1/2, 1/4,
  // 1/4): H = 1.5 log3 2 = 0.9464 (the "0.95" quoted for it, rounded),
  // A = 0, alpha = 45 deg (eigenvectors e1 = [1 0 0], e2, e3 in the T22-T33
  // plane).
  const CloudePottier v = cloude_pottier(t3_from_c3(dipole_volume_c3(0.3)));
  EXPECT_NEAR(v.entropy, 1.5 * std::log(2.0) / std::log(3.0), 1e-9);
  EXPECT_GT(v.entropy, 0.94);
  EXPECT_NEAR(v.anisotropy, 0.0, 1e-9);
  EXPECT_NEAR(v.alpha_rad * kDeg, 45.0, 1e-6);
  // Unpolarised (T3 = I): H 1, alpha 60 (Cloude & Pottier 1997).
  Hermitian3 id;
  id(0, 0) = id(1, 1) = id(2, 2) = 1.0;
  EXPECT_NEAR(cloude_pottier(id).entropy, 1.0, 1e-12);
  EXPECT_NEAR(cloude_pottier(id).alpha_rad * kDeg, 60.0, 1e-6);
}

TEST(CloudePottier, SmallPerturbationSurface) {
  test::TempDir dir;
  test::write_file(dir / "lib.toml", R"(
[library]
name = "spm"
[[category]]
id = 1
name = "smooth soil"
colour = "#808080"
[category.model]
name = "spm"
rms_height = "0.3 cm"
correlation_length = "5 cm"
correlation = "exponential"
permittivity = "15 - 3j"
)");
  auto src = load_sigma0_source((dir / "lib.toml").string());
  for (double deg : {20.0, 35.0, 50.0}) {
    const Hermitian3 c3 = category_covariance(*src, 1, deg_to_rad(deg), 1.26e9);  // ks = 0.08
    const CloudePottier s = cloude_pottier(t3_from_c3(c3));
    // The Bragg alpha grows with incidence (23.6 deg at 50 deg for eps 15): the
    // issue's "below 20 deg" holds at moderate incidence.
    if (deg < 45.0) {
      EXPECT_LT(s.alpha_rad * kDeg, 20.0) << deg;
    }
    EXPECT_LT(s.entropy, 0.3) << deg;
    // Rank one: alpha = atan(|HH - VV| / |HH + VV|) exactly.
    const double hh = std::sqrt(c3(0, 0).real()), vv = std::sqrt(c3(2, 2).real());
    EXPECT_NEAR(s.alpha_rad, std::atan(std::abs(hh - vv) / (hh + vv)), 1e-6) << deg;
  }
}

TEST(FreemanDurden, RecoversSyntheticMixtures) {
  // Surface dominant (Re C13 >= 0, alpha = -1 as the branch assumes).
  {
    const double fs = 0.5, fd = 0.2, fv = 0.3;
    const Complex beta(0.6, 0.2);
    const Hermitian3 c = surface_c3(fs, beta) + dihedral_c3(fd, -1.0) + dipole_volume_c3(fv);
    const FreemanDurden f = freeman_durden(c);
    const double ps = fs * (1 + std::norm(beta)), pd = 2 * fd, pv = 8 * fv / 3;
    EXPECT_NEAR(f.surface, ps, 0.02 * ps);
    EXPECT_NEAR(f.double_bounce, pd, 0.02 * pd);
    EXPECT_NEAR(f.volume, pv, 0.02 * pv);
    EXPECT_NEAR(f.surface + f.double_bounce + f.volume, c.trace(), 1e-12);
  }
  // Double bounce dominant (Re C13 < 0, beta = 1).
  {
    const double fs = 0.2, fd = 0.6, fv = 0.15;
    const Complex alpha(-0.7, 0.3);
    const Hermitian3 c = surface_c3(fs, 1.0) + dihedral_c3(fd, alpha) + dipole_volume_c3(fv);
    const FreemanDurden f = freeman_durden(c);
    const double ps = 2 * fs, pd = fd * (1 + std::norm(alpha)), pv = 8 * fv / 3;
    EXPECT_NEAR(f.surface, ps, 0.02 * ps);
    EXPECT_NEAR(f.double_bounce, pd, 0.02 * pd);
    EXPECT_NEAR(f.volume, pv, 0.02 * pv);
  }
  // All volume: nothing else.
  const FreemanDurden v = freeman_durden(dipole_volume_c3(0.4));
  EXPECT_NEAR(v.volume, 0.4 * 8 / 3, 1e-12);
  EXPECT_NEAR(v.surface + v.double_bounce, 0.0, 1e-12);
  // More HV than the co-pol channels can hold: PolSARpro's case 1, all volume.
  Hermitian3 odd = dipole_volume_c3(0.4);
  odd(1, 1) = 2.0;
  const FreemanDurden o = freeman_durden(odd);
  EXPECT_NEAR(o.volume, odd.trace(), 1e-12);
  EXPECT_EQ(o.surface + o.double_bounce, 0.0);
}

TEST(FreemanDurden, ImageClipsToTheSpanRange) {
  CovarianceImage img;
  img.cols = 2;
  img.rows = 1;
  img.m = {surface_c3(1.0, 0.5), dipole_volume_c3(0.1)};
  const std::vector<FreemanDurden> f = freeman_durden_image(img);
  const double span_min = img.m[1].trace(), span_max = img.m[0].trace();
  for (const FreemanDurden& p : f) {
    for (double v : {p.surface, p.double_bounce, p.volume}) {
      EXPECT_GE(v, span_min);
      EXPECT_LE(v, span_max);
    }
  }
}

TEST(PauliRgb, ColoursOfCanonicalTargets) {
  // Odd bounce blue, double bounce red, HV green (PolSARpro's Pauli colours).
  CovarianceImage img;
  img.cols = 3;
  img.rows = 1;
  img.is_t3 = true;
  img.m = {t3_of({1.0, 0.0, 0.0, 1.0}), t3_of({1.0, 0.0, 0.0, -1.0}), t3_of({0.0, 1.0, 1.0, 0.0})};
  const std::vector<std::uint8_t> rgb = pauli_rgb(img);
  EXPECT_TRUE(rgb[0] == 0 && rgb[1] == 0 && rgb[2] > 0);  // trihedral: blue
  EXPECT_TRUE(rgb[3] > 0 && rgb[4] == 0 && rgb[5] == 0);  // dihedral: red
  EXPECT_TRUE(rgb[6] == 0 && rgb[7] > 0 && rgb[8] == 0);  // 45 deg dihedral: green
}

TEST(CovarianceImage, BoxcarAndMultilook) {
  CovarianceImage img;
  img.cols = 5;
  img.rows = 4;
  for (int i = 0; i < 20; ++i) {
    Hermitian3 m;
    m(0, 0) = i;
    img.m.push_back(m);
  }
  const CovarianceImage b = boxcar_average(img, 3, 3);
  EXPECT_DOUBLE_EQ(b.m[6](0, 0).real(), 6.0);                    // interior: mean of a linear ramp
  EXPECT_DOUBLE_EQ(b.m[0](0, 0).real(), (0 + 1 + 5 + 6) / 4.0);  // corner: 2 x 2 inside
  const CovarianceImage ml = multilook(img, 2, 2);
  ASSERT_EQ(ml.cols, 2);
  ASSERT_EQ(ml.rows, 2);
  EXPECT_DOUBLE_EQ(ml.m[0](0, 0).real(), (0 + 1 + 5 + 6) / 4.0);
  EXPECT_DOUBLE_EQ(ml.m[3](0, 0).real(), (12 + 13 + 17 + 18) / 4.0);
  const CovarianceImage back = to_c3(to_t3(img));
  EXPECT_NEAR(back.m[7](0, 0).real(), 7.0, 1e-12);
}

}  // namespace
}  // namespace ris
