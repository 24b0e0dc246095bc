// The 3 x 3 covariance C3 (lexicographic basis, ris/backscatter/
// polarimetric_matrix.h) of a backscatter category at a band, and a sampler
// of scattering vectors with that covariance (issue 33, docs/polarimetry.md).
//
// The diagonal comes from the sigma0 the category's model already gives per
// channel: C11 = sigma0_HH, C22 = 2 sigma0_HV, C33 = sigma0_VV (per unit
// area; the models' outputs are not changed). The off-diagonal follows the
// category's polarimetric shape:
//   coherent_surface   SPM and IEM surfaces (spm, i2em): first-order
//                      scattering is fully polarised, S_HH / S_VV =
//                      alpha_HH / alpha_VV, so C13 = sqrt(C11 C33) (|rho| = 1;
//                      phase 0: both Bragg coefficients are real and negative
//                      for a real permittivity; a lossy soil's few-degree phase
//                      is not modelled);
//   dipole_volume      a cloud of randomly oriented thin dipoles:
//                      C3 = span (3/8) [1 0 1/3; 0 2/3 0; 1/3 0 1]
//                      (Freeman & Durden 1998, eq. 7; span = C11 + C22 + C33
//                      from the model's channels);
//   correlated         intensity-only models (oh1992, oh2004, dubois1995,
//                      water_cloud, table, ulaby_dobson, ...):
//                      C13 = rho sqrt(C11 C33) with a documented default rho
//                      per model family (default_polarimetry).
// Reflection symmetry everywhere: C12 = C23 = 0 (Nghiem, Yueh, Kwok & Li,
// Radio Sci. 27(5), 1992: a medium with a mirror plane through the look
// direction decorrelates co- and cross-polarised returns).
//
// Example:
//   auto src = ris::load_sigma0_source("data/backscatter/ku-geometric.toml");
//   ris::Hermitian3 c3 = ris::category_covariance(*src, 4, ris::deg_to_rad(30.0), 9.6e9);
//   ris::CovarianceSampler sampler(c3);
//   ris::Vector3c k = sampler.sample(seed, element_index);  // <k k^H> = c3
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "ris/backscatter/polarimetric_matrix.h"
#include "ris/backscatter/sigma0_source.h"

namespace ris {

enum class CovarianceShape { coherent_surface, dipole_volume, correlated };

struct CategoryPolarimetry {
  CovarianceShape shape = CovarianceShape::correlated;
  Complex rho_hhvv = 0.0;  // correlated only: <HH VV*> / sqrt(<|HH|^2><|VV|^2>)
  std::string source;      // where the shape or rho comes from (docs, metadata)
};

// The shape of a model family by its registered name (the first word of
// Sigma0Source::category_model: "spm", "water_cloud", "table", ...); an
// unknown name gets the intensity-only default.
CategoryPolarimetry default_polarimetry(const std::string& model_name);

// The shape of a category of src at a frequency: its model family's
// default_polarimetry (the first word of its HH model description).
CategoryPolarimetry category_polarimetry(const Sigma0Source& src, std::uint16_t category,
                                         double frequency_hz);

// Where a covariance is made, for messages: the library file, the category
// (name and id), the band and the key that set the shape.
struct CovarianceWhere {
  std::string file;
  std::string category;
  double frequency_hz = 0.0;
  std::string key;
};

struct ChannelSigma0 {
  double hh = 0.0, hv = 0.0, vv = 0.0;  // linear, per unit area
};

// C3 of the header from the three channels and a shape. InputError naming
// where.file, the category, the band and where.key when the result is not
// Hermitian positive semidefinite (|rho| > 1, a negative or non-finite
// sigma0).
Hermitian3 covariance_from_channels(const ChannelSigma0& s, const CategoryPolarimetry& p,
                                    const CovarianceWhere& where);

// C3 of a category of src at a local incidence and frequency: its HH, HV and
// VV sigma0 (a model that gives no HV, dubois1995, is refused naming the
// category and band) and the model family's default_polarimetry unless
// `shape` says otherwise.
Hermitian3 category_covariance(const Sigma0Source& src, std::uint16_t category,
                               double incidence_rad, double frequency_hz,
                               const std::optional<CategoryPolarimetry>& shape = std::nullopt);

// Scattering vectors k = L z with L L^H = C3 (cholesky_lower) and z a unit
// complex Gaussian vector (E z z^H = I: real and imaginary parts N(0, 1/2),
// ziggurat normals of the counter-based generator keyed by (seed, element
// index), CounterRng stream kPolarimetryStream): E k k^H = C3, and each
// element's vector depends on (seed, index) only, never on thread or order.
class CovarianceSampler {
 public:
  static constexpr std::uint32_t kPolarimetryStream = 0x504F4C00u;  // "POL\0"

  explicit CovarianceSampler(const Hermitian3& c3);  // RIS_CHECK: Hermitian PSD
  Vector3c sample(std::uint64_t seed, std::uint64_t element) const;
  const Hermitian3& factor() const { return l_; }

 private:
  Hermitian3 l_;
};

}  // namespace ris
