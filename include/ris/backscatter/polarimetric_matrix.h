// The polarimetric algebra of a reciprocal, monostatic radar (docs/polarimetry.md):
// the Sinclair matrix S, its scattering vectors in the lexicographic and the
// Pauli basis, the 3 x 3 covariance C3 and coherency T3 and their
// conversion, the Hermitian positive-semidefinite check and a Cholesky
// factor that accepts rank-deficient matrices.
//
// It sits in the backscatter layer because that is the lowest layer that
// needs it (a category's covariance, ris/backscatter/category_covariance.h);
// the image layer's decompositions (ris/image/polsar/) use it from above.
//
// Conventions (Lee & Pottier, "Polarimetric Radar Imaging", CRC 2009, ch. 3;
// Cloude & Pottier, IEEE TGRS 34(2), 1996):
//   k_L = [S_HH, sqrt2 S_HV, S_VV]                 C3 = < k_L k_L^H >
//   k_P = [S_HH + S_VV, S_HH - S_VV, 2 S_HV] / sqrt2  T3 = < k_P k_P^H >
//   k_P = U k_L,  U = [1 0 1; 1 0 -1; 0 sqrt2 0] / sqrt2,  T3 = U C3 U^H
// S_HV of a measured pair is (S_HV + S_VH) / 2 (reciprocity, PolSARpro's S2
// to T3); span = trace C3 = trace T3 = |HH|^2 + 2|HV|^2 + |VV|^2.
//
// Example:
//   ris::Sinclair s{1.0, 0.0, 0.0, -1.0};        // a dihedral
//   ris::Hermitian3 t = ris::outer(ris::pauli_vector(s));  // t(1,1) == 2
#pragma once

#include <array>
#include <complex>
#include <string>

namespace ris {

using Complex = std::complex<double>;
using Vector3c = std::array<Complex, 3>;

// One pixel's scattering matrix, S_rt (r: receive, t: transmit).
struct Sinclair {
  Complex hh, hv, vh, vv;
};

// A 3 x 3 complex matrix, row-major; a C3 or T3 when Hermitian.
struct Hermitian3 {
  std::array<Complex, 9> m{};
  Complex& operator()(int r, int c) { return m[static_cast<std::size_t>(3 * r + c)]; }
  const Complex& operator()(int r, int c) const { return m[static_cast<std::size_t>(3 * r + c)]; }
  double trace() const { return m[0].real() + m[4].real() + m[8].real(); }
};

Hermitian3 operator+(const Hermitian3& a, const Hermitian3& b);
Hermitian3 operator*(double s, const Hermitian3& a);

Vector3c lexicographic_vector(const Sinclair& s);
Vector3c pauli_vector(const Sinclair& s);
// k k^H.
Hermitian3 outer(const Vector3c& k);
// T3 = U C3 U^H and C3 = U^H T3 U.
Hermitian3 t3_from_c3(const Hermitian3& c3);
Hermitian3 c3_from_t3(const Hermitian3& t3);

// Eigenvalues of a Hermitian matrix (its Hermitian part), descending, and
// the unit eigenvectors in the same order (eigenvectors[i] for values[i]);
// Eigen's SelfAdjointEigenSolver.
struct HermitianEigen {
  std::array<double, 3> values{};
  std::array<Vector3c, 3> vectors{};
};
HermitianEigen hermitian_eigen(const Hermitian3& a);

// Whether a is Hermitian (|a_ij - conj a_ji| <= tol * trace) and positive
// semidefinite (smallest eigenvalue >= -tol * trace), tol = 1e-9; when not,
// `why` says which (an element, or the negative eigenvalue).
bool is_hermitian_psd(const Hermitian3& a, std::string* why = nullptr);

// A lower-triangular L with L L^H = a for a Hermitian PSD a (RIS_CHECKed by
// the caller): Cholesky-Banachiewicz, a pivot at or below 1e-12 * trace
// taken as zero with its column below set to zero, so the rank-deficient
// covariances of fully correlated channels (SPM: HH and VV coherent) factor.
Hermitian3 cholesky_lower(const Hermitian3& a);

}  // namespace ris
