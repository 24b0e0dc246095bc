// The polarimetric algebra of ris/backscatter/polarimetric_matrix.h.
#include "ris/backscatter/polarimetric_matrix.h"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>

namespace ris {

namespace {

constexpr double kSqrt2 = 1.41421356237309504880;
constexpr double kTolerance = 1e-9;

// U of the header (k_P = U k_L).
Hermitian3 pauli_from_lexicographic() {
  const double r = 1.0 / kSqrt2;
  Hermitian3 u;
  u(0, 0) = r;
  u(0, 2) = r;
  u(1, 0) = r;
  u(1, 2) = -r;
  u(2, 1) = 1.0;
  return u;
}

// a b, and a b^H.
Hermitian3 product(const Hermitian3& a, const Hermitian3& b, bool b_adjoint) {
  Hermitian3 out;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      Complex s = 0.0;
      for (int k = 0; k < 3; ++k) s += a(r, k) * (b_adjoint ? std::conj(b(c, k)) : b(k, c));
      out(r, c) = s;
    }
  }
  return out;
}

Hermitian3 adjoint(const Hermitian3& a) {
  Hermitian3 out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out(r, c) = std::conj(a(c, r));
  return out;
}

}  // namespace

Hermitian3 operator+(const Hermitian3& a, const Hermitian3& b) {
  Hermitian3 out;
  for (std::size_t i = 0; i < 9; ++i) out.m[i] = a.m[i] + b.m[i];
  return out;
}

Hermitian3 operator*(double s, const Hermitian3& a) {
  Hermitian3 out;
  for (std::size_t i = 0; i < 9; ++i) out.m[i] = s * a.m[i];
  return out;
}

Vector3c lexicographic_vector(const Sinclair& s) {
  const Complex hv = 0.5 * (s.hv + s.vh);
  return {s.hh, kSqrt2 * hv, s.vv};
}

Vector3c pauli_vector(const Sinclair& s) {
  const Complex hv = 0.5 * (s.hv + s.vh);
  return {(s.hh + s.vv) / kSqrt2, (s.hh - s.vv) / kSqrt2, kSqrt2 * hv};
}

Hermitian3 outer(const Vector3c& k) {
  Hermitian3 out;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c)
      out(r, c) = k[static_cast<std::size_t>(r)] * std::conj(k[static_cast<std::size_t>(c)]);
  return out;
}

Hermitian3 t3_from_c3(const Hermitian3& c3) {
  const Hermitian3 u = pauli_from_lexicographic();
  return product(product(u, c3, false), u, true);
}

Hermitian3 c3_from_t3(const Hermitian3& t3) {
  const Hermitian3 uh = adjoint(pauli_from_lexicographic());
  return product(product(uh, t3, false), uh, true);
}

HermitianEigen hermitian_eigen(const Hermitian3& a) {
  Eigen::Matrix3cd m;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = 0.5 * (a(r, c) + std::conj(a(c, r)));
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3cd> solver(m);
  HermitianEigen out;
  // Eigen sorts ascending; ris's order is descending.
  for (int i = 0; i < 3; ++i) {
    const int j = 2 - i;
    out.values[static_cast<std::size_t>(i)] = solver.eigenvalues()(j);
    for (int k = 0; k < 3; ++k)
      out.vectors[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)] =
          solver.eigenvectors()(k, j);
  }
  return out;
}

bool is_hermitian_psd(const Hermitian3& a, std::string* why) {
  const double scale = std::max(std::abs(a.trace()), 1e-300);
  for (int r = 0; r < 3; ++r) {
    for (int c = r; c < 3; ++c) {
      const double d = std::abs(a(r, c) - std::conj(a(c, r)));
      if (!(d <= kTolerance * scale)) {
        if (why != nullptr) {
          *why = fmt::format("element ({},{}) is not the conjugate of ({},{}) (off by {:g})", r + 1,
                             c + 1, c + 1, r + 1, d);
        }
        return false;
      }
    }
  }
  const HermitianEigen e = hermitian_eigen(a);
  if (!(e.values[2] >= -kTolerance * scale) || !(a.trace() >= 0.0)) {
    if (why != nullptr) {
      *why = fmt::format(
          "not positive semidefinite: eigenvalue {:g} (trace {:g}); a correlation above 1 in "
          "magnitude or a negative power makes one",
          e.values[2], a.trace());
    }
    return false;
  }
  return true;
}

Hermitian3 cholesky_lower(const Hermitian3& a) {
  const double floor = 1e-12 * std::max(a.trace(), 0.0);
  Hermitian3 l;
  for (int j = 0; j < 3; ++j) {
    double d = a(j, j).real();
    for (int k = 0; k < j; ++k) d -= std::norm(l(j, k));
    if (d <= floor) continue;  // a zero pivot: this column of L stays zero
    const double ljj = std::sqrt(d);
    l(j, j) = ljj;
    for (int i = j + 1; i < 3; ++i) {
      Complex s = a(i, j);
      for (int k = 0; k < j; ++k) s -= l(i, k) * std::conj(l(j, k));
      l(i, j) = s / ljj;
    }
  }
  return l;
}

}  // namespace ris
