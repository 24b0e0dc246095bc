// The quad-pol coherent SAR (ris/sim/sar_quad_pol.h): each element's factor
// reproduces its covariance exactly; over a homogeneous field the images'
// sample covariance is the category's C3 (powers, rho_HHVV, zero co-/cross
// correlation) within its standard error; single-look intensity is
// exponential in every channel; HV = VH without noise; a trihedral target
// has HH = VV and no HV; the images do not depend on the thread count.
#include "ris/sim/sar_quad_pol.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <complex>
#include <cstring>
#include <string>

#include "ris/backscatter/category_covariance.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/error.h"

namespace ris {
namespace {

using cd = std::complex<double>;

// sigma0_pq = g_pq cos(theta) with HH 0.10, HV 0.02, VV 0.15 (per unit
// area); category 0 a table (rho 0.6 by default_polarimetry), category 1 an
// SPM surface (fully correlated).
class PolSigma0Source : public Sigma0Source {
 public:
  bool has_category(std::uint16_t c) const override { return c <= 1; }
  double sigma0(std::uint16_t, double theta, const RadarBand& band) const override {
    return gain(band.polarisation) * std::cos(theta);
  }
  std::string category_name(std::uint16_t c) const override { return "cat" + std::to_string(c); }
  std::string description() const override { return "test: polarised gamma cos(theta)"; }
  std::string category_model(std::uint16_t c, const RadarBand&) const override {
    return c == 1 ? "spm (test)" : "table (test)";
  }
  static double gain(Polarisation p) {
    switch (p) {
      case Polarisation::HH:
        return 0.10;
      case Polarisation::VV:
        return 0.15;
      default:
        return 0.02;
    }
  }
};

// The coherent SAR test's geometry (sar_coherent_test.cpp): 1 m cells,
// 1000 m along track, 200 m across, the track 1000 m west at 1000 m.
RadarParams quad_radar(const std::string& extra = "") {
  return radar_from_toml(toml::parse(R"(
mode = "sar"
frequency = "9.6 GHz"
polarisation = "HH"
near_range = "1420 m"
far_range = "1550 m"
range_bin = "1 m"
transmit_power = "1 kW"
[sar]
range_resolution = "3 m"
azimuth_resolution = "3 m"
coherent = true
quad_pol = true
)" + extra + R"(
[track]
altitude = "1000 m"
near_edge_distance = "1000 m"
)"),
                         "quad.toml");
}

struct QuadRunForTest {
  std::vector<SlarSimulation> sims;
  CategoryShapes shapes;
  std::vector<PointTarget> targets;
  QuadPolImages form(std::uint64_t seed) const {
    return form_quad_pol({&sims[0], &sims[1], &sims[2]}, shapes, targets, seed);
  }
};

QuadRunForTest run_quad(const Scene& scene, const RadarParams& radar, const SlarOptions& o = {}) {
  static const PolSigma0Source src;
  QuadRunForTest r;
  r.sims = simulate_quad_pol_channels(scene, radar, src, o);
  r.shapes = scene_polarimetry(scene, src, radar);
  r.targets = o.targets;
  return r;
}

// L L^H of an element factor (reflection-symmetric lower triangle).
Hermitian3 product(const ElementFactor& f) {
  Hermitian3 l;
  l(0, 0) = f.l11;
  l(1, 1) = f.l22;
  l(2, 0) = f.l31;
  l(2, 2) = f.l33;
  Hermitian3 out;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k) out(i, j) += l(i, k) * std::conj(l(j, k));
  return out;
}

TEST(SarQuadPol, ElementFactorReproducesTheCategoryCovariance) {
  const ChannelSigma0 s{0.10, 0.02, 0.15};
  const CovarianceWhere where{"test", "cat", 9.6e9, "model"};
  const std::vector<CategoryPolarimetry> shapes = {
      {CovarianceShape::correlated, std::polar(0.6, 0.3), ""},
      {CovarianceShape::coherent_surface, 1.0, ""},
      {CovarianceShape::dipole_volume, 0.0, ""},
      {CovarianceShape::correlated, 0.0, ""}};
  for (const CategoryPolarimetry& p : shapes) {
    const Hermitian3 c3 = covariance_from_channels(s, p, where);
    const Hermitian3 llh = product(element_factor(s.hh, s.hv, s.vv, {p.shape, p.rho_hhvv}));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        EXPECT_NEAR(std::abs(llh(i, j) - c3(i, j)), 0.0, 1e-12)
            << "shape " << static_cast<int>(p.shape) << " element " << i << j;
  }
  // No HH power: HH's column is zero, VV keeps its power.
  const ElementFactor f = element_factor(0.0, 0.02, 0.15, {CovarianceShape::correlated, 0.6});
  EXPECT_EQ(f.l11, 0.0);
  EXPECT_EQ(std::abs(f.l31), 0.0);
  EXPECT_NEAR(f.l33 * f.l33, 0.15, 1e-15);
}

// Sample statistics of the interior pixels, pooled over seeds: each channel's
// |z|^2 over its mean power (the incoherent image of that channel), the ENL,
// and the normalised correlations <a b*> / sqrt(<|a|^2><|b|^2>).
struct FieldStats {
  std::array<double, 4> mean_ratio{}, enl{};
  cd rho_hhvv, rho_hhhv, rho_hvvv;
};

FieldStats field_stats(const QuadRunForTest& run, std::initializer_list<std::uint64_t> seeds) {
  const SlarImage& img = run.sims[0].image;
  std::array<const SlarImage*, 4> mean = {&run.sims[0].image, &run.sims[1].image,
                                          &run.sims[1].image, &run.sims[2].image};
  std::array<double, 4> s{}, s2{};
  cd hhvv = 0.0, hhhv = 0.0, hvvv = 0.0;
  std::array<double, 4> pw{};
  double n = 0.0;
  for (std::uint64_t seed : seeds) {
    const QuadPolImages q = run.form(seed);
    for (int line = 40; line < img.lines - 40; ++line)
      for (int b = 15; b < img.bins - 15; ++b) {
        const std::size_t i = img.index(line, b);
        for (std::size_t c = 0; c < 4; ++c) {
          const double v = q.intensity[c][i] / mean[c]->mean_power_w[i];
          s[c] += v;
          s2[c] += v * v;
          pw[c] += q.intensity[c][i];
        }
        const cd hh = q.slc[0][i], hv = q.slc[1][i], vv = q.slc[3][i];
        hhvv += hh * std::conj(vv);
        hhhv += hh * std::conj(hv);
        hvvv += hv * std::conj(vv);
        n += 1.0;
      }
  }
  FieldStats out;
  for (std::size_t c = 0; c < 4; ++c) {
    const double m = s[c] / n;
    out.mean_ratio[c] = m;
    out.enl[c] = m * m / (s2[c] / n - m * m);
  }
  out.rho_hhvv = hhvv / std::sqrt(pw[0] * pw[3]);
  out.rho_hhhv = hhhv / std::sqrt(pw[0] * pw[1]);
  out.rho_hvvv = hvvv / std::sqrt(pw[1] * pw[3]);
  return out;
}

// About 20,000 independent resolution cells a realisation (3 m x 3 m cells
// over 920 m x 170 m), three realisations: the standard error of a mean
// ratio is 1/sqrt(60,000) = 0.4 %, of the ENL about 1 %, of a correlation
// (1 - |rho|^2)/sqrt(60,000) < 0.4 %; the tolerances are 5 standard errors
// or more.
TEST(SarQuadPol, HomogeneousFieldHasTheCategoryCovariance) {
  const QuadRunForTest run = run_quad(Scene::flat(1000, 200, 1.0, 0.0f, 0), quad_radar());
  const FieldStats f = field_stats(run, {7, 8, 9});
  for (std::size_t c = 0; c < 4; ++c) {
    EXPECT_NEAR(f.mean_ratio[c], 1.0, 0.02) << "channel " << c;
    EXPECT_NEAR(f.enl[c], 1.0, 0.06) << "channel " << c;
  }
  EXPECT_NEAR(f.rho_hhvv.real(), 0.6, 0.02);  // the table family's default
  EXPECT_NEAR(f.rho_hhvv.imag(), 0.0, 0.02);
  EXPECT_NEAR(std::abs(f.rho_hhhv), 0.0, 0.02);  // reflection symmetry
  EXPECT_NEAR(std::abs(f.rho_hvvv), 0.0, 0.02);
}

TEST(SarQuadPol, SpmSurfaceIsFullyCorrelated) {
  const QuadRunForTest run = run_quad(Scene::flat(1000, 200, 1.0, 0.0f, 1), quad_radar());
  const FieldStats f = field_stats(run, {11});
  EXPECT_GT(std::abs(f.rho_hhvv), 0.999);
  EXPECT_NEAR(std::arg(f.rho_hhvv), 0.0, 1e-3);
  EXPECT_NEAR(f.mean_ratio[3], 1.0, 0.03);
}

TEST(SarQuadPol, ReciprocalImagesWithoutNoiseAreEqualAndNoiseIsIndependent) {
  const QuadRunForTest quiet = run_quad(Scene::flat(300, 200, 1.0, 0.0f, 0), quad_radar());
  const QuadPolImages q = quiet.form(3);
  ASSERT_EQ(q.slc[1].size(), q.slc[2].size());
  EXPECT_EQ(std::memcmp(q.slc[1].data(), q.slc[2].data(), q.slc[1].size() * sizeof(q.slc[1][0])),
            0);
  // With an NESZ each channel has its own noise: HV and VH differ.
  const QuadRunForTest noisy =
      run_quad(Scene::flat(300, 200, 1.0, 0.0f, 0), quad_radar("nesz_db = -10\n"));
  const QuadPolImages n = noisy.form(3);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < n.slc[1].size(); ++i) differ += n.slc[1][i] != n.slc[2][i];
  EXPECT_GT(differ, n.slc[1].size() / 2);
}

TEST(SarQuadPol, ImagesDoNotDependOnTheThreadCount) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(1);
  const QuadRunForTest one = run_quad(Scene::flat(300, 200, 1.0, 0.0f, 0), quad_radar());
  const QuadPolImages a = one.form(5);
  omp_set_num_threads(2);
  const QuadRunForTest two = run_quad(Scene::flat(300, 200, 1.0, 0.0f, 0), quad_radar());
  const QuadPolImages b = two.form(5);
  omp_set_num_threads(before);
  for (std::size_t c = 0; c < 4; ++c) {
    ASSERT_EQ(a.slc[c].size(), b.slc[c].size());
    EXPECT_EQ(std::memcmp(a.slc[c].data(), b.slc[c].data(), a.slc[c].size() * sizeof(a.slc[c][0])),
              0)
        << "channel " << c;
  }
}

// A user's point target is a trihedral: S = sqrt(rcs) I. On a field 40 dB
// darker than it, the peak pixel has HH = VV (same phase) and HV near 0.
TEST(SarQuadPol, TrihedralTargetHasEqualCoPolAndNoCrossPol) {
  SlarOptions o;
  PointTarget t;
  t.name = "cr";
  t.x_m = 100.0;
  t.y_m = 150.0;
  t.rcs_m2 = 1e4;
  o.targets.push_back(t);
  const QuadRunForTest run = run_quad(Scene::flat(300, 200, 1.0, 0.0f, 0), quad_radar(), o);
  const QuadPolImages q = run.form(1);
  std::size_t peak = 0;
  for (std::size_t i = 0; i < q.intensity[0].size(); ++i)
    if (q.intensity[0][i] > q.intensity[0][peak]) peak = i;
  const cd hh = q.slc[0][peak], hv = q.slc[1][peak], vv = q.slc[3][peak];
  // The clutter's share at the peak: sigma0 ~ 0.1 x 9 m^2 cells against 1e4 m^2.
  EXPECT_NEAR(std::abs(vv / hh), 1.0, 0.05);
  EXPECT_NEAR(std::arg(vv / hh), 0.0, 0.05);
  EXPECT_LT(std::norm(hv) / std::norm(hh), 1e-3);
}

}  // namespace
}  // namespace ris
