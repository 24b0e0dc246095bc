// A category's polarimetric covariance and its sampler
// (ris/backscatter/category_covariance.h, docs/polarimetry.md).
#include "ris/backscatter/category_covariance.h"

#include <fmt/format.h>

#include <cmath>

#include "ris/util/counter_rng.h"
#include "ris/util/error.h"
#include "ris/util/ziggurat_normal.h"

namespace ris {

namespace {

// The intensity-only families and their default co-polarised correlation.
// Engineering defaults inside the ranges the literature reports, not fits to
// the categories (a library column for rho is the way to measured values,
// docs/polarimetry.md): bare soil keeps HH and VV nearly in phase (narrow
// co-pol phase-difference distributions, Ulaby, Held, Dobson, McDonald &
// Senior, IEEE TGRS GE-25(1), 1987; Sarabandi, IEEE TGRS 30(4), 1992);
// vegetation canopies decorrelate them (wide distributions, same sources;
// the dipole volume's 1/3 is the fully random limit); an empirical table or
// fit knows nothing of the mechanism and takes a value between.
constexpr double kBareSoilRho = 0.85;
constexpr double kVegetationRho = 0.45;
constexpr double kEmpiricalRho = 0.6;

constexpr const char* kSoilSource =
    "default rho 0.85 for bare soil (Ulaby et al. 1987; Sarabandi 1992; docs/polarimetry.md)";
constexpr const char* kVegetationSource =
    "default rho 0.45 for vegetation (Ulaby et al. 1987; docs/polarimetry.md)";
constexpr const char* kEmpiricalSource =
    "default rho 0.6 for an empirical model or table (docs/polarimetry.md)";

std::string band_text(double frequency_hz) {
  return fmt::format("{:g} GHz", frequency_hz / 1e9);
}

std::string first_word(const std::string& s) {
  const auto end = s.find(' ');
  return end == std::string::npos ? s : s.substr(0, end);
}

}  // namespace

CategoryPolarimetry default_polarimetry(const std::string& model_name) {
  if (model_name == "spm" || model_name == "i2em") {
    return {CovarianceShape::coherent_surface, 1.0,
            "first-order surface scattering: HH and VV fully correlated (Bragg ratio)"};
  }
  if (model_name == "oh1992" || model_name == "oh2004" || model_name == "dubois1995") {
    return {CovarianceShape::correlated, kBareSoilRho, kSoilSource};
  }
  if (model_name == "water_cloud") {
    return {CovarianceShape::correlated, kVegetationRho, kVegetationSource};
  }
  return {CovarianceShape::correlated, kEmpiricalRho, kEmpiricalSource};
}

Hermitian3 covariance_from_channels(const ChannelSigma0& s, const CategoryPolarimetry& p,
                                    const CovarianceWhere& where) {
  const auto refuse = [&](const std::string& what) {
    throw InputError(where.file, where.key,
                     fmt::format("category {} at {}: the covariance is not Hermitian positive "
                                 "semidefinite: {}",
                                 where.category, band_text(where.frequency_hz), what));
  };
  for (const auto& [name, v] : {std::pair{"HH", s.hh}, {"HV", s.hv}, {"VV", s.vv}}) {
    if (!std::isfinite(v) || v < 0.0) refuse(fmt::format("sigma0 {} is {:g}", name, v));
  }
  Hermitian3 c;
  switch (p.shape) {
    case CovarianceShape::dipole_volume: {
      const double f = 3.0 / 8.0 * (s.hh + 2.0 * s.hv + s.vv);
      c(0, 0) = f;
      c(1, 1) = f * 2.0 / 3.0;
      c(2, 2) = f;
      c(0, 2) = c(2, 0) = f / 3.0;
      return c;
    }
    case CovarianceShape::coherent_surface:
    case CovarianceShape::correlated: {
      const Complex rho = p.shape == CovarianceShape::coherent_surface ? Complex(1.0) : p.rho_hhvv;
      if (!std::isfinite(rho.real()) || !std::isfinite(rho.imag()) || std::abs(rho) > 1.0) {
        refuse(fmt::format("|rho_HHVV| = {:g} (expected at most 1)", std::abs(rho)));
      }
      c(0, 0) = s.hh;
      c(1, 1) = 2.0 * s.hv;
      c(2, 2) = s.vv;
      c(0, 2) = rho * std::sqrt(s.hh * s.vv);
      c(2, 0) = std::conj(c(0, 2));
      break;
    }
  }
  std::string why;
  if (!is_hermitian_psd(c, &why)) refuse(why);
  return c;
}

CategoryPolarimetry category_polarimetry(const Sigma0Source& src, std::uint16_t category,
                                         double frequency_hz) {
  return default_polarimetry(
      first_word(src.category_model(category, RadarBand{frequency_hz, Polarisation::HH})));
}

Hermitian3 category_covariance(const Sigma0Source& src, std::uint16_t category,
                               double incidence_rad, double frequency_hz,
                               const std::optional<CategoryPolarimetry>& shape) {
  const RadarBand hh{frequency_hz, Polarisation::HH};
  const std::string name = fmt::format("'{}' ({})", src.category_name(category), category);
  ChannelSigma0 s;
  s.hh = src.sigma0(category, incidence_rad, hh);
  s.vv = src.sigma0(category, incidence_rad, {frequency_hz, Polarisation::VV});
  try {
    s.hv = src.sigma0(category, incidence_rad, {frequency_hz, Polarisation::HV});
  } catch (const InputError& e) {
    throw InputError(e.file(), e.key(),
                     fmt::format("category {} at {}: its covariance needs sigma0 HV, which the "
                                 "model does not give ({}); give the category a model with HV "
                                 "(a band entry for HV)",
                                 name, band_text(frequency_hz), e.what()));
  }
  const std::string model = first_word(src.category_model(category, hh));
  const CategoryPolarimetry p = shape ? *shape : default_polarimetry(model);
  const CovarianceWhere where{src.description(), name, frequency_hz,
                              shape ? "rho_hhvv" : "model " + model};
  return covariance_from_channels(s, p, where);
}

CovarianceSampler::CovarianceSampler(const Hermitian3& c3) : l_(cholesky_lower(c3)) {
  RIS_CHECK(is_hermitian_psd(c3));
}

Vector3c CovarianceSampler::sample(std::uint64_t seed, std::uint64_t element) const {
  const ZigguratTables& zig = ziggurat_tables();
  CounterRng rng(seed, static_cast<std::uint32_t>(element),
                 static_cast<std::uint32_t>(element >> 32), kPolarimetryStream);
  constexpr double kHalf = 0.70710678118654752440;  // E|z|^2 = 1
  Vector3c z;
  for (Complex& zi : z) {
    const double re = ziggurat_normal(rng, zig);
    const double im = ziggurat_normal(rng, zig);
    zi = Complex(re * kHalf, im * kHalf);
  }
  Vector3c k{};
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c <= r; ++c)
      k[static_cast<std::size_t>(r)] += l_(r, c) * z[static_cast<std::size_t>(c)];
  return k;
}

}  // namespace ris
