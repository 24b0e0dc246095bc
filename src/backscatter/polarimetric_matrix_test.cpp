#include "ris/backscatter/polarimetric_matrix.h"

#include <gtest/gtest.h>

#include <cmath>

namespace ris {
namespace {

double max_diff(const Hermitian3& a, const Hermitian3& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < 9; ++i) d = std::max(d, std::abs(a.m[i] - b.m[i]));
  return d;
}

Hermitian3 example_c3() {
  Hermitian3 c;
  c(0, 0) = 2.0;
  c(1, 1) = 0.6;
  c(2, 2) = 1.0;
  c(0, 1) = Complex(0.1, 0.2);
  c(1, 0) = std::conj(c(0, 1));
  c(0, 2) = Complex(0.5, -0.3);
  c(2, 0) = std::conj(c(0, 2));
  c(1, 2) = Complex(-0.05, 0.1);
  c(2, 1) = std::conj(c(1, 2));
  return c;
}

TEST(PolarimetricMatrix, PauliAndLexicographicVectorsOfKnownTargets) {
  // A trihedral (S = I) is all first Pauli component; a dihedral all
  // second; a 45 deg rotated dihedral (S = [0 1; 1 0]) all third.
  const Vector3c tri = pauli_vector({1.0, 0.0, 0.0, 1.0});
  EXPECT_NEAR(std::abs(tri[0]), std::sqrt(2.0), 1e-15);
  EXPECT_EQ(std::abs(tri[1]) + std::abs(tri[2]), 0.0);
  const Vector3c di = pauli_vector({1.0, 0.0, 0.0, -1.0});
  EXPECT_NEAR(std::abs(di[1]), std::sqrt(2.0), 1e-15);
  const Vector3c rot = pauli_vector({0.0, 1.0, 1.0, 0.0});
  EXPECT_NEAR(std::abs(rot[2]), std::sqrt(2.0), 1e-15);
  EXPECT_EQ(std::abs(rot[0]) + std::abs(rot[1]), 0.0);
  // sqrt2 on HV: span |HH|^2 + 2|HV|^2 + |VV|^2 in both bases.
  const Sinclair s{Complex(1, 2), Complex(0.3, -0.1), Complex(0.3, -0.1), Complex(-0.5, 0.4)};
  const Vector3c kl = lexicographic_vector(s);
  EXPECT_NEAR(std::abs(kl[1]), std::sqrt(2.0) * std::abs(s.hv), 1e-15);
  const double span = std::norm(s.hh) + 2 * std::norm(s.hv) + std::norm(s.vv);
  EXPECT_NEAR(outer(kl).trace(), span, 1e-13);
  EXPECT_NEAR(outer(pauli_vector(s)).trace(), span, 1e-13);
}

TEST(PolarimetricMatrix, C3ToT3IsTheOuterProductOfThePauliVector) {
  const Sinclair s{Complex(1, 2), Complex(0.3, -0.1), Complex(0.3, -0.1), Complex(-0.5, 0.4)};
  const Hermitian3 c3 = outer(lexicographic_vector(s));
  EXPECT_LT(max_diff(t3_from_c3(c3), outer(pauli_vector(s))), 1e-14);
  const Hermitian3 c = example_c3();
  EXPECT_LT(max_diff(c3_from_t3(t3_from_c3(c)), c), 1e-14);
  // T11 = <|HH+VV|^2>/2 of C3: (C11 + C33 + 2 Re C13) / 2.
  EXPECT_NEAR(t3_from_c3(c)(0, 0).real(), (2.0 + 1.0 + 2 * 0.5) / 2, 1e-15);
}

TEST(PolarimetricMatrix, EigenDecompositionAndCholeskyReconstruct) {
  const Hermitian3 c = example_c3();
  const HermitianEigen e = hermitian_eigen(c);
  EXPECT_GE(e.values[0], e.values[1]);
  EXPECT_GE(e.values[1], e.values[2]);
  Hermitian3 back;
  for (std::size_t i = 0; i < 3; ++i) back = back + e.values[i] * outer(e.vectors[i]);
  EXPECT_LT(max_diff(back, c), 1e-13);
  const Hermitian3 l = cholesky_lower(c);
  Hermitian3 llh;
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 3; ++col)
      for (int k = 0; k < 3; ++k) llh(r, col) += l(r, k) * std::conj(l(col, k));
  EXPECT_LT(max_diff(llh, c), 1e-14);
  EXPECT_EQ(std::abs(l(0, 1)) + std::abs(l(0, 2)) + std::abs(l(1, 2)), 0.0);  // lower
}

TEST(PolarimetricMatrix, CholeskyFactorsRankDeficientCovariance) {
  // Fully correlated HH and VV (an SPM surface): rank 1 in that block, HV 0.
  Hermitian3 c;
  c(0, 0) = 0.04;
  c(2, 2) = 0.09;
  c(0, 2) = c(2, 0) = 0.06;
  EXPECT_TRUE(is_hermitian_psd(c));
  const Hermitian3 l = cholesky_lower(c);
  Hermitian3 llh;
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 3; ++col)
      for (int k = 0; k < 3; ++k) llh(r, col) += l(r, k) * std::conj(l(col, k));
  EXPECT_LT(max_diff(llh, c), 1e-15);
}

TEST(PolarimetricMatrix, RefusesNonHermitianAndIndefinite) {
  Hermitian3 c = example_c3();
  std::string why;
  EXPECT_TRUE(is_hermitian_psd(c, &why));
  c(0, 2) = Complex(2.0, 0.0);  // |rho| > 1 with C11 C33 = 2
  c(2, 0) = Complex(2.0, 0.0);
  EXPECT_FALSE(is_hermitian_psd(c, &why));
  EXPECT_NE(why.find("positive semidefinite"), std::string::npos) << why;
  Hermitian3 d = example_c3();
  d(1, 0) = d(0, 1);  // not conjugated
  EXPECT_FALSE(is_hermitian_psd(d, &why));
  EXPECT_NE(why.find("conjugate"), std::string::npos) << why;
}

}  // namespace
}  // namespace ris
