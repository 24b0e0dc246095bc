#include "ris/backscatter/category_covariance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ris/backscatter/library.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

using test::TempDir;
using test::write_file;

// A library with one category per polarimetric family (L band).
constexpr const char* kLibrary = R"toml(
[library]
name = "polarimetry test"
[[category]]
id = 1
name = "smooth soil (spm)"
colour = "#808080"
[category.model]
name = "spm"
rms_height = "0.4 cm"
correlation_length = "5 cm"
correlation = "exponential"
permittivity = "15 - 3j"
[[category]]
id = 2
name = "bare soil (oh1992)"
colour = "#808080"
[category.model]
name = "oh1992"
rms_height = "1 cm"
permittivity = "15 - 3j"
[[category]]
id = 3
name = "grass (water cloud)"
colour = "#808080"
[category.model]
name = "water_cloud"
A = 0.1
B = 0.1
V1 = 1.0
V2 = 0.5
[category.model.ground]
name = "oh1992"
rms_height = "1 cm"
permittivity = "15 - 3j"
[[category]]
id = 4
name = "dubois soil"
colour = "#808080"
[category.model]
name = "dubois1995"
rms_height = "1 cm"
permittivity = "15 - 3j"
)toml";

constexpr double kLBand = 1.26e9;

// The sample covariance of n vectors drawn by a sampler of c3, each element
// against C3: |S_ij - C_ij| / sqrt(C_ii C_jj), the largest.
double sample_error(const Hermitian3& c3, std::uint64_t n, std::uint64_t seed) {
  const CovarianceSampler sampler(c3);
  Hermitian3 sum;
  for (std::uint64_t i = 0; i < n; ++i) sum = sum + outer(sampler.sample(seed, i));
  const Hermitian3 s = (1.0 / static_cast<double>(n)) * sum;
  double worst = 0.0;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) {
      const double scale = std::sqrt(c3(r, r).real() * c3(c, c).real());
      if (scale > 0.0) worst = std::max(worst, std::abs(s(r, c) - c3(r, c)) / scale);
    }
  return worst;
}

TEST(CategoryCovariance, ShapesFollowTheModelFamily) {
  TempDir dir;
  write_file(dir / "lib.toml", kLibrary);
  auto src = load_sigma0_source((dir / "lib.toml").string());
  const double t = deg_to_rad(35.0);
  // SPM: HH and VV fully correlated, no HV, the diagonal the model's sigma0.
  const Hermitian3 spm = category_covariance(*src, 1, t, kLBand);
  EXPECT_DOUBLE_EQ(spm(0, 0).real(), src->sigma0(1, t, {kLBand, Polarisation::HH}));
  EXPECT_DOUBLE_EQ(spm(2, 2).real(), src->sigma0(1, t, {kLBand, Polarisation::VV}));
  EXPECT_EQ(spm(1, 1).real(), 0.0);
  EXPECT_NEAR(std::abs(spm(0, 2)), std::sqrt(spm(0, 0).real() * spm(2, 2).real()), 1e-15);
  // Oh: C22 = 2 sigma0_HV, the bare-soil default rho; reflection symmetry.
  const Hermitian3 oh = category_covariance(*src, 2, t, kLBand);
  EXPECT_DOUBLE_EQ(oh(1, 1).real(), 2.0 * src->sigma0(2, t, {kLBand, Polarisation::HV}));
  EXPECT_NEAR(std::abs(oh(0, 2)) / std::sqrt(oh(0, 0).real() * oh(2, 2).real()), 0.85, 1e-12);
  EXPECT_EQ(std::abs(oh(0, 1)) + std::abs(oh(1, 2)), 0.0);
  const Hermitian3 wc = category_covariance(*src, 3, t, kLBand);
  EXPECT_NEAR(std::abs(wc(0, 2)) / std::sqrt(wc(0, 0).real() * wc(2, 2).real()), 0.45, 1e-12);
  // A dipole volume asked for: span kept, the [1 0 1/3; 0 2/3 0; 1/3 0 1] shape.
  const Hermitian3 vol = category_covariance(
      *src, 3, t, kLBand, CategoryPolarimetry{CovarianceShape::dipole_volume, 0.0, ""});
  EXPECT_NEAR(vol.trace(), wc.trace(), 1e-15);
  EXPECT_NEAR(vol(1, 1).real() / vol(0, 0).real(), 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(vol(0, 2).real() / vol(0, 0).real(), 1.0 / 3.0, 1e-15);
}

TEST(CategoryCovariance, RefusesNonPsdAndModelsWithoutHv) {
  TempDir dir;
  write_file(dir / "lib.toml", kLibrary);
  auto src = load_sigma0_source((dir / "lib.toml").string());
  const double t = deg_to_rad(35.0);
  try {
    category_covariance(*src, 2, t, kLBand,
                        CategoryPolarimetry{CovarianceShape::correlated, Complex(0.9, 0.6), ""});
    FAIL() << "|rho| = 1.08 accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("bare soil (oh1992)"), std::string::npos) << m;
    EXPECT_NE(m.find("1.26 GHz"), std::string::npos) << m;
    EXPECT_NE(m.find("rho_hhvv"), std::string::npos) << m;
  }
  try {
    category_covariance(*src, 4, t, 5.3e9);
    FAIL() << "dubois1995 gives no HV but a covariance was made";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("dubois soil"), std::string::npos) << m;
    EXPECT_NE(m.find("HV"), std::string::npos) << m;
  }
  EXPECT_THROW(covariance_from_channels({-1.0, 0.0, 1.0}, {}, {"f", "c", 1e9, "k"}), InputError);
}

// Issue 33's statistics: 10^6 sampled elements of each family.
TEST(CategoryCovarianceSampler, SampleCovarianceWithinOnePercentOfC3) {
  TempDir dir;
  write_file(dir / "lib.toml", kLibrary);
  auto src = load_sigma0_source((dir / "lib.toml").string());
  const double t = deg_to_rad(35.0);
  for (std::uint16_t id : {std::uint16_t{1}, std::uint16_t{2}, std::uint16_t{3}}) {
    const Hermitian3 c3 = category_covariance(*src, id, t, kLBand);
    const double err = sample_error(c3, 1000000, 42);
    EXPECT_LT(err, 0.01) << "category " << id;
    RecordProperty("max_rel_error_category_" + std::to_string(id), std::to_string(err));
  }
  // A full-rank matrix with every element nonzero.
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
  EXPECT_LT(sample_error(c, 1000000, 7), 0.01);
}

TEST(CategoryCovarianceSampler, DeterministicByElementAndSeed) {
  Hermitian3 c;
  c(0, 0) = c(1, 1) = c(2, 2) = 1.0;
  const CovarianceSampler s(c);
  const Vector3c a = s.sample(5, 123456789012ull);
  const Vector3c b = s.sample(5, 123456789012ull);
  EXPECT_EQ(a, b);
  EXPECT_NE(s.sample(6, 123456789012ull), a);
  EXPECT_NE(s.sample(5, 123456789013ull), a);
  EXPECT_NE(s.sample(5, 123456789012ull + (1ull << 32)), a);  // high word keyed too
}

// Single look: each channel's intensity exponential (ENL 1; P(I > mean) = 1/e).
TEST(CategoryCovarianceSampler, SingleLookIntensityIsExponential) {
  Hermitian3 c;
  c(0, 0) = 2.0;
  c(1, 1) = 0.6;
  c(2, 2) = 1.0;
  c(0, 2) = c(2, 0) = 0.8;
  const CovarianceSampler s(c);
  constexpr std::uint64_t kN = 1000000;
  for (std::size_t ch = 0; ch < 3; ++ch) {
    double sum = 0.0, sum2 = 0.0;
    std::uint64_t above = 0;
    const double mean_true = c(static_cast<int>(ch), static_cast<int>(ch)).real();
    for (std::uint64_t i = 0; i < kN; ++i) {
      const double p = std::norm(s.sample(11, i)[ch]);
      sum += p;
      sum2 += p * p;
      above += p > mean_true ? 1 : 0;
    }
    const double m = sum / kN, var = sum2 / kN - m * m;
    const double enl = m * m / var;
    // Delta method for exponential data: var(ENL^) = 4 / N.
    const double se = 2.0 / std::sqrt(static_cast<double>(kN));
    EXPECT_LT(std::abs(enl - 1.0), 3.0 * se) << "channel " << ch << " ENL " << enl;
    const double frac = static_cast<double>(above) / kN;
    const double se_frac = std::sqrt(std::exp(-1.0) * (1 - std::exp(-1.0)) / kN);
    EXPECT_LT(std::abs(frac - std::exp(-1.0)), 4.0 * se_frac) << "channel " << ch;
    RecordProperty("enl_minus_1_in_se_channel_" + std::to_string(ch),
                   std::to_string((enl - 1.0) / se));
  }
}

// n looks: C3 averaged over n independent vectors is complex Wishart,
// n C^ ~ W(n, C): E C^ = C and var C^_ii = C_ii^2 / n (Goodman 1963; Lee &
// Pottier 2009, sec. 4.2).
TEST(CategoryCovarianceSampler, MultilookDiagonalVarianceIsWishart) {
  Hermitian3 c;
  c(0, 0) = 2.0;
  c(1, 1) = 0.6;
  c(2, 2) = 1.0;
  c(0, 2) = Complex(0.8, 0.3);
  c(2, 0) = std::conj(c(0, 2));
  const CovarianceSampler s(c);
  constexpr int kLooks = 4;
  constexpr std::uint64_t kM = 250000;  // 10^6 elements
  std::array<double, 3> sum{}, sum2{};
  for (std::uint64_t j = 0; j < kM; ++j) {
    Hermitian3 acc;
    for (int l = 0; l < kLooks; ++l) acc = acc + outer(s.sample(3, j * kLooks + l));
    for (int d = 0; d < 3; ++d) {
      const double v = acc(d, d).real() / kLooks;
      sum[static_cast<std::size_t>(d)] += v;
      sum2[static_cast<std::size_t>(d)] += v * v;
    }
  }
  for (int d = 0; d < 3; ++d) {
    const auto i = static_cast<std::size_t>(d);
    const double m = sum[i] / kM, var = sum2[i] / kM - m * m;
    const double expected = c(d, d).real() * c(d, d).real() / kLooks;
    // var of a sample variance of Gamma(n) data: sigma^4 (2 + 6 / n) / M.
    const double se = expected * std::sqrt((2.0 + 6.0 / kLooks) / kM);
    EXPECT_LT(std::abs(var - expected), 4.0 * se) << "C" << d + 1 << d + 1 << " var " << var;
    EXPECT_LT(std::abs(m - c(d, d).real()), 0.01 * c(d, d).real());
  }
}

}  // namespace
}  // namespace ris
