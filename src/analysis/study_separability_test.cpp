// The study's separability at matched geometry (ris/analysis/study_separability.h):
// the closed forms, the statistics on hand-made pixels, the null check and a
// constructed case whose best band and JM distance are known.
#include "ris/analysis/study_separability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ris/analysis/study.h"
#include "ris/backscatter/library.h"
#include "ris/sensor/radar_config.h"
#include "test_inputs.h"
#include "test_util.h"

namespace ris {
namespace {

using test::TempDir;
using test::write_file;

// The Bhattacharyya coefficient of two gamma densities of shape L and means
// m_a, m_b, integral of sqrt(p_a p_b) by the midpoint rule, against the
// closed form (L ln((m_a + m_b) / (2 sqrt(m_a m_b)))).
TEST(StudySeparability, GammaBhattacharyyaIsTheIntegralOfTheDensities) {
  for (const double looks : {1.0, 4.0, 23.5}) {
    for (const double ratio : {1.0, 1.5, 4.0}) {
      const double ma = 1.0, mb = ratio;
      const auto pdf = [&](double x, double m) {
        const double theta = m / looks;
        return std::exp((looks - 1.0) * std::log(x) - x / theta - std::lgamma(looks) -
                        looks * std::log(theta));
      };
      double bc = 0.0;
      const double dx = 1e-4;
      for (double x = 0.5 * dx; x < 40.0; x += dx) bc += std::sqrt(pdf(x, ma) * pdf(x, mb)) * dx;
      EXPECT_NEAR(gamma_bhattacharyya(ma, mb, looks), -std::log(bc), 2e-4)
          << "L " << looks << " ratio " << ratio;
    }
  }
  EXPECT_DOUBLE_EQ(gamma_bhattacharyya(2.0, 2.0, 7.0), 0.0);
  EXPECT_DOUBLE_EQ(gamma_bhattacharyya(1.0, 3.0, 5.0), gamma_bhattacharyya(3.0, 1.0, 5.0));
  EXPECT_DOUBLE_EQ(jeffries_matusita(0.0), 0.0);
  EXPECT_NEAR(jeffries_matusita(std::log(2.0)), 1.0, 1e-15);
  EXPECT_NEAR(jeffries_matusita(50.0), 2.0, 1e-15);
}

TEST(StudySeparability, NormalQuantiles) {
  EXPECT_NEAR(normal_two_sided_quantile(0.05), 1.959964, 1e-6);
  EXPECT_NEAR(normal_two_sided_quantile(0.0026998), 3.0, 1e-4);
  EXPECT_NEAR(normal_two_sided_quantile(1e-6), 4.891638, 1e-6);
}

// Hand-made pixels in one incidence bin: category 1 alternates 1 and 3
// (mean 2, sample deviation sqrt(4/3 * n/(n-1)) ...), category 2 is 2 + tiny.
TEST(StudySeparability, StatisticsOfOneBin) {
  const int n = 40;
  std::vector<std::int32_t> labels;
  std::vector<double> cal, looks;
  for (int i = 0; i < n; ++i) {
    labels.push_back(1);
    cal.push_back(i % 2 == 0 ? 1.0 : 3.0);
    looks.push_back(4.0);
    labels.push_back(2);
    cal.push_back(i % 2 == 0 ? 6.0 : 2.0);  // mean 4
    looks.push_back(4.0);
  }
  labels.push_back(3);  // too few pixels: category 3 is not compared
  cal.push_back(1.0);
  looks.push_back(4.0);
  IncidenceBins ib;
  ib.count = 1;
  ib.bin.assign(labels.size(), 0);
  ib.incidence_rad.assign(labels.size(), 0.5f);  // one incidence: no trend
  const BandSeparability s =
      band_separability(labels, ib, cal, looks, {1, 2, 3}, SeparabilityOptions{3.0, 20});
  ASSERT_EQ(s.bins.size(), 1u);
  const PairBin& b = s.bins[0];
  EXPECT_EQ(b.pixels_a, n);
  EXPECT_DOUBLE_EQ(b.mean_a, 2.0);
  EXPECT_DOUBLE_EQ(b.mean_b, 4.0);
  // sd_a = sqrt(n / (n - 1)) (values +-1 about 2), sd_b = 2 sqrt(n / (n - 1)):
  // both relative errors sqrt(n/(n-1)) / (2 sqrt n).
  const double rel = std::sqrt(double(n) / (n - 1)) / (2.0 * std::sqrt(double(n)));
  EXPECT_NEAR(b.sigma_log, std::sqrt(2.0) * rel, 1e-12);
  EXPECT_NEAR(b.z, std::log(0.5) / (std::sqrt(2.0) * rel), 1e-9);
  EXPECT_NEAR(b.jm, 2.0 * (1.0 - std::pow(3.0 / (2.0 * std::sqrt(2.0)), -4.0)), 1e-12);
  ASSERT_EQ(s.pairs.size(), 3u);
  EXPECT_TRUE(s.pairs[0].separated);                // |z| = 5.5 > 3
  EXPECT_NEAR(s.pairs[0].delta_db, -3.0103, 1e-4);  // 10 log10(2 / 4)
  EXPECT_EQ(s.pairs[1].bins, 0);                    // 1 / 3: no bin
  EXPECT_TRUE(std::isnan(s.pairs[1].jm));
  EXPECT_EQ(s.compared_pairs, 1);
  EXPECT_EQ(s.separated_pairs, 1);
  EXPECT_DOUBLE_EQ(s.score, b.jm);
}

// One law I = exp(20 t) (+-10 % noise) for two categories lying at the two
// halves of one incidence bin (t 0-9 and 10-19 mrad): compared at the pair's
// mean incidence along the bin's common trend they agree; their plain means
// differ by 20 x 10 mrad = 0.87 dB, far beyond the sampling error.
TEST(StudySeparability, TrendInsideABinIsRemovedBeforeComparing) {
  std::vector<std::int32_t> labels;
  std::vector<double> cal, looks;
  IncidenceBins ib;
  ib.count = 1;
  for (int c = 1; c <= 2; ++c) {
    for (int p = 0; p < 400; ++p) {
      const double t = 0.01 * (c - 1) + 0.001 * (p % 10);
      labels.push_back(c);
      cal.push_back(std::exp(20.0 * t) * ((p / 10) % 2 == 0 ? 0.9 : 1.1));
      looks.push_back(10.0);
      ib.bin.push_back(0);
      ib.incidence_rad.push_back(static_cast<float>(t));
    }
  }
  const BandSeparability s =
      band_separability(labels, ib, cal, looks, {1, 2}, SeparabilityOptions{3.0, 20});
  ASSERT_EQ(s.pairs.size(), 1u);
  EXPECT_NEAR(s.pairs[0].delta_db, 0.0, 0.02);
  EXPECT_FALSE(s.pairs[0].separated) << s.pairs[0].z;
  // The plain means: 10 log10(exp(-0.2)) = -0.869 dB apart.
  double m1 = 0.0, m2 = 0.0;
  for (std::size_t i = 0; i < 400; ++i) m1 += cal[i] / 400.0, m2 += cal[400 + i] / 400.0;
  EXPECT_NEAR(10.0 * std::log10(m1 / m2), -0.869, 0.01);
}

// A flat scene of 40 x 40-cell squares (400 m) in a checkerboard of two
// categories, so that each lies at every range in turn: compared where they
// lie (the old contrast) they differ by position alone.
Scene checkerboard() {
  Scene s = Scene::flat(120, 200, 10.0, 0.0f, 1);
  for (int r = 0; r < 120; ++r) {
    for (int c = 0; c < 200; ++c) {
      s.category[s.index(r, c)] = static_cast<std::uint16_t>(1 + (r / 40 + c / 40) % 2);
    }
  }
  return s;
}

// Constant N = 8 looks, so the JM of two categories is one closed form in
// every bin; exact gamma fading.
const std::string kRadar = test::kSmallSlarRadar + R"(
[film]
gamma = 0.4
fading = "exact"
)";
const std::string kLooks = "independent_samples = 8\n";

RadarParams radar(bool constant_looks) {
  return radar_from_toml(toml::parse((constant_looks ? kLooks : "") + kRadar), "radar.toml");
}

std::unique_ptr<Sigma0Source> write_library(const TempDir& dir, const std::string& text) {
  const std::string path = (dir / "lib.toml").string();
  write_file(path, text);
  return load_sigma0_source(path);
}

// Null check: one and the same backscatter (Muhleman's law, which falls 4 dB
// over the swath) for both categories gives no separated pair at any band,
// and the study names no best band; its own null runs agree.
TEST(StudySeparability, NullCheckOneBackscatterForAllSeparatesNothing) {
  const TempDir dir;
  const auto sigma0 = write_library(dir, R"(
[[category]]
id = 1
name = "grass"
colour = "#30a030"
[category.model]
name = "muhleman"
[[category]]
id = 2
name = "crop"
colour = "#a0a030"
[category.model]
name = "muhleman"
)");
  const auto bands = parse_study_bands("1.25 GHz:HH, 8.6 GHz:VV, 13 GHz:HH", "--bands");
  const StudyResult r = run_study(checkerboard(), radar(false), *sigma0, "lib.toml", bands);
  ASSERT_EQ(r.panels.size(), 3u);
  EXPECT_GT(r.incidence.count, 3);
  // Bonferroni over 3 bands x 1 pair at a family error of 1 %.
  EXPECT_DOUBLE_EQ(r.z_critical, normal_two_sided_quantile(0.01 / 3.0));
  EXPECT_NEAR(r.z_critical, 2.935, 1e-3);
  for (const StudyPanel& p : r.panels) {
    ASSERT_EQ(p.separability.pairs.size(), 1u);
    const PairSeparability& s = p.separability.pairs[0];
    EXPECT_GT(s.bins, 3) << p.band.label();
    EXPECT_FALSE(s.separated) << p.band.label() << " z " << s.z;
    EXPECT_LT(std::abs(s.z), r.z_critical);
    // Zero within the sampling error: the JM of the estimates is of the
    // order of the noise level (JM of a one-standard-error log ratio).
    EXPECT_LT(s.jm, 10.0 * s.jm_noise) << p.band.label();
    EXPECT_NEAR(s.delta_db, 0.0, 0.15) << p.band.label();
    EXPECT_EQ(p.separability.score, 0.0);
  }
  EXPECT_EQ(r.best_panel, -1);
  EXPECT_EQ(study_verdict(r), "no band separates these categories");
  EXPECT_TRUE(r.null_check_run);
  EXPECT_TRUE(r.null_check_passed);
}

// Constructed case: crop is 3 dB above grass at 8.6 GHz only (constant
// gamma), equal elsewhere. With N = 8 looks the speckled laws are
// Gamma(8, m / 8) and B = 8 ln((1 + r) / (2 sqrt r)), r = 10^0.3:
// B = 0.467975, JM = 2 (1 - e^-B) = 0.747462.
TEST(StudySeparability, ConstructedCaseGivesTheBandAndTheClosedFormJm) {
  const TempDir dir;
  const auto sigma0 = write_library(dir, R"(
[[category]]
id = 1
name = "grass"
colour = "#30a030"
[category.model]
name = "constant_gamma"
gamma_db = -10.0
[[category]]
id = 2
name = "crop"
colour = "#a0a030"
[category.model]
name = "constant_gamma"
gamma_db = -10.0
[[category.band]]
frequency = ["8 GHz", "9 GHz"]
[category.band.model]
name = "constant_gamma"
gamma_db = -7.0
)");
  const auto bands = parse_study_bands("1.25 GHz:HH, 8.6 GHz:HH, 13 GHz:HH", "--bands");
  const StudyResult r = run_study(checkerboard(), radar(true), *sigma0, "lib.toml", bands);
  ASSERT_EQ(r.panels.size(), 3u);
  EXPECT_EQ(r.best_panel, 1);
  EXPECT_EQ(study_verdict(r), "best band: 8.6 GHz HH");
  const double ratio = std::pow(10.0, 0.3);
  const double jm =
      2.0 * (1.0 - std::exp(-8.0 * std::log((1.0 + ratio) / (2.0 * std::sqrt(ratio)))));
  EXPECT_NEAR(jm, 0.747462, 1e-6);
  const PairSeparability& x = r.panels[1].separability.pairs[0];
  EXPECT_TRUE(x.separated);
  EXPECT_NEAR(x.delta_db, -3.0, 0.1);  // grass / crop
  // The estimate's error: a few noise levels at most.
  EXPECT_NEAR(x.jm, jm, 0.03);
  for (const PairBin& b : r.panels[1].separability.bins) {
    EXPECT_DOUBLE_EQ(b.looks, 8.0);
    EXPECT_NEAR(b.jm, jm, 0.15) << b.bin;
    // Calibrated: the means are sigma0 itself, gamma cos t at the bin's
    // incidence (within 0.3 dB: a few standard errors and the bin's width).
    const double t = r.incidence.first_lo_rad + (b.bin + 0.5) * r.incidence.width_rad;
    EXPECT_NEAR(10.0 * std::log10(b.mean_a), -10.0 + 10.0 * std::log10(std::cos(t)), 0.3);
    EXPECT_NEAR(10.0 * std::log10(b.mean_b), -7.0 + 10.0 * std::log10(std::cos(t)), 0.3);
  }
  for (int i : {0, 2}) {
    EXPECT_FALSE(r.panels[i].separability.pairs[0].separated) << r.panels[i].band.label();
    EXPECT_EQ(r.panels[i].separability.score, 0.0);
  }
  EXPECT_TRUE(r.null_check_passed);
}

// The window: only range bins whose centre lies in the interval, and only
// pixels whose contributors share one incidence bin.
TEST(StudySeparability, WindowKeepsTheChosenRangeInterval) {
  const TempDir dir;
  const auto sigma0 = write_library(
      dir, test::constant_gamma_library({{1, "grass", -12.0, ""}, {2, "crop", -6.0, ""}}));
  const RadarParams rp = radar_for_band(radar(false), {8.6e9, Polarisation::HH});
  SlarOptions keep;
  keep.keep_geometry = true;
  const SlarSimulation sim = simulate_slar(checkerboard(), rp, *sigma0, keep);
  const PixelAttribution at = attribute_pixels(sim);
  StudyWindow w;
  w.range_lo_fraction = 1.0 / 3.0;
  w.range_hi_fraction = 2.0 / 3.0;
  const IncidenceBins ib = incidence_bins(sim, at, w);
  const double extent = sim.image.bins * sim.image.range.bin_m;
  EXPECT_NEAR(ib.range_lo_m, sim.image.range.near_m + extent / 3.0, 1e-6);
  int inside = 0;
  for (int k = 0; k < sim.image.bins; ++k) {
    const double rc = sim.image.range.centre_m(k);
    for (int l = 0; l < sim.image.lines; ++l) {
      const std::size_t p = sim.image.index(l, k);
      if (ib.bin[p] < 0) continue;
      ++inside;
      EXPECT_GE(rc, ib.range_lo_m);
      EXPECT_LE(rc, ib.range_hi_m);
      EXPECT_GE(at.category[p], 1);
      const double lo = ib.first_lo_rad + ib.bin[p] * ib.width_rad;
      EXPECT_GE(at.incidence_lo_rad[p], lo - 1e-6);
      EXPECT_LE(at.incidence_hi_rad[p], lo + ib.width_rad + 1e-6);
    }
  }
  EXPECT_GT(inside, sim.image.lines * sim.image.bins / 6);
}

}  // namespace
}  // namespace ris
