// Coherent SAR: speckle from the physics (ENL 1 single look, L for L looks),
// impulse-response widths and sidelobes of a point target, the same azimuth
// resolution at near and far range, thread independence.
#include "ris/sim/sar_coherent.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "ris/image/impulse_response.h"
#include "ris/sensor/radar_config.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

// 1 m cells, 1000 m along track, 200 m across; track 1000 m west at 1000 m.
// The length keeps the ENL estimate's sampling error near 2% (the pixels are
// correlated over a resolution cell: ~20,000 independent ones).
Scene speckle_scene() {
  return Scene::flat(1000, 200, 1.0, 0.0f, 0);
}

RadarParams coherent_radar(const std::string& extra = "") {
  return radar_from_toml(toml::parse(R"(
mode = "sar"
frequency = "9.6 GHz"
polarisation = "VV"
near_range = "1420 m"
far_range = "1550 m"
range_bin = "1 m"
transmit_power = "1 kW"
[sar]
range_resolution = "3 m"
azimuth_resolution = "3 m"
coherent = true
)" + extra + R"(
[track]
altitude = "1000 m"
near_edge_distance = "1000 m"
)"),
                         "sar.toml");
}

// ENL = mean^2 / variance of I / E[I] over the image's interior, pooled over
// the realisations given.
double enl(const SlarSimulation& sim, const std::vector<std::vector<float>>& intensities) {
  const SlarImage& img = sim.image;
  double s = 0.0, s2 = 0.0;
  int n = 0;
  for (const std::vector<float>& intensity : intensities)
    for (int line = 40; line < img.lines - 40; ++line)
      for (int b = 15; b < img.bins - 15; ++b) {
        const std::size_t i = img.index(line, b);
        const double v = intensity[i] / img.mean_power_w[i];
        s += v;
        s2 += v * v;
        ++n;
      }
  const double mean = s / n;
  EXPECT_NEAR(mean, 1.0, 0.05);  // E|z|^2 is the incoherent mean power
  return mean * mean / (s2 / n - mean * mean);
}

TEST(SarCoherent, SingleLookUniformAreaHasExponentialIntensity) {
  const SlarSimulation sim =
      simulate_slar(speckle_scene(), coherent_radar(), test::CosineSigma0Source());
  // Three seeds pooled: sampling error ~1.2% against the 5% tolerance.
  const std::vector<float> intensity = coherent_sar_intensity(sim, 7);
  EXPECT_NEAR(enl(sim, {intensity, coherent_sar_intensity(sim, 8), coherent_sar_intensity(sim, 9)}),
              1.0, 0.05);
  // Exponential: P(I > E) = exp(-1) = 0.368.
  const SlarImage& img = sim.image;
  int above = 0, n = 0;
  for (int line = 40; line < img.lines - 40; ++line)
    for (int b = 15; b < img.bins - 15; ++b, ++n)
      if (intensity[img.index(line, b)] > img.mean_power_w[img.index(line, b)]) ++above;
  EXPECT_NEAR(double(above) / n, std::exp(-1.0), 0.02);
}

// E|z|^2 of the coherent sum is the incoherent mean power (MODEL.md section
// 3; the truncated sinc's energy renormalised): pooled over 24 single-look
// realisations (~480,000 independent resolution cells, a standard error of
// 0.14% for the exponential law), the mean ratio is 1 within 0.5%.
TEST(SarCoherent, CoherentMeanPowerEqualsTheIncoherentImage) {
  const SlarSimulation sim =
      simulate_slar(speckle_scene(), coherent_radar(), test::CosineSigma0Source());
  const SlarImage& img = sim.image;
  double sum = 0.0;
  std::int64_t n = 0;
  for (std::uint64_t seed = 100; seed < 124; ++seed) {
    const std::vector<float> intensity = coherent_sar_intensity(sim, seed);
    for (int line = 40; line < img.lines - 40; ++line) {
      for (int b = 15; b < img.bins - 15; ++b) {
        const std::size_t i = img.index(line, b);
        sum += intensity[i] / img.mean_power_w[i];
        ++n;
      }
    }
  }
  // Measured 0.99978; without the renormalisation it would be 0.976.
  EXPECT_NEAR(sum / double(n), 1.0, 5e-3);
}

TEST(SarCoherent, FourLookAverageHasEnlFour) {
  const SlarSimulation sim =
      simulate_slar(speckle_scene(), coherent_radar("range_looks = 2\nazimuth_looks = 2\n"),
                    test::CosineSigma0Source());
  EXPECT_NEAR(enl(sim, {coherent_sar_intensity(sim, 7)}), 4.0, 0.4);
}

TEST(SarCoherent, PointTargetResolutionAndSidelobesMatchTheDesign) {
  SlarOptions opt;
  for (double x : {30.0, 170.0}) {  // near (u = 1030 m) and far (u = 1170 m)
    PointTarget t;
    t.name = "cr";
    t.x_m = x + 0.5;
    t.y_m = 130.5;
    t.rcs_m2 = 1e5;
    opt.targets.push_back(t);
  }
  const SlarSimulation sim =
      simulate_slar(speckle_scene(), coherent_radar(), test::CosineSigma0Source(), opt);
  ASSERT_EQ(sim.point_returns.size(), 2u);
  const std::vector<float> intensity = coherent_sar_intensity(sim, 3);
  const SlarImage& img = sim.image;
  for (const PointReturn& pr : sim.point_returns) {
    const int bin = static_cast<int>((pr.slant_range_m - img.range.near_m) / img.range.bin_m);
    const IrfMeasurement m =
        measure_irf(intensity, img.lines, img.bins, img.line_spacing_m, img.range.bin_m, pr.line,
                    bin, 3, 24, IrfInterpolation::sinc);
    // Measured within 4e-4 of the design's 3 m (sinc interpolation of 1 m
    // pixels); the clutter is 50 dB below the target.
    EXPECT_NEAR(m.range.width_m / 3.0, 1.0, 4e-3) << "R " << pr.slant_range_m;
    EXPECT_NEAR(m.azimuth.width_m / 3.0, 1.0, 4e-3) << "R " << pr.slant_range_m;
    // An unweighted sinc: first sidelobe -13.26 dB (measured within 0.11 dB);
    // ISLR -10.2 dB within the +-24-pixel cuts, as ris/image/impulse_response's
    // own test of a clean sinc (measured -10.38 and -10.41).
    EXPECT_NEAR(m.range.pslr_db, -13.26, 0.3);
    EXPECT_NEAR(m.azimuth.pslr_db, -13.26, 0.3);
    EXPECT_NEAR(m.islr_db, -10.2, 0.5);
  }
}

TEST(SarCoherent, SameSeedSameBytesForOneAndTwoThreads) {
  SlarOptions opt;
  PointTarget t;
  t.name = "cr";
  t.x_m = 100.0;
  t.y_m = 100.0;
  t.rcs_m2 = 100.0;
  opt.targets.push_back(t);
  const RadarParams r = coherent_radar("nesz_db = -20\nazimuth_looks = 2\n");
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const SlarSimulation a = simulate_slar(speckle_scene(), r, test::CosineSigma0Source(), opt);
  const std::vector<float> ia = coherent_sar_intensity(a, 11);
  omp_set_num_threads(2);
  const SlarSimulation b = simulate_slar(speckle_scene(), r, test::CosineSigma0Source(), opt);
  const std::vector<float> ib = coherent_sar_intensity(b, 11);
  omp_set_num_threads(saved);
  ASSERT_EQ(ia.size(), ib.size());
  EXPECT_EQ(0, std::memcmp(ia.data(), ib.data(), ia.size() * sizeof(float)));
  const SlarPictures pa = render_slar(a, 11, ia), pb = render_slar(b, 11, ib);
  EXPECT_EQ(pa.slant_grey, pb.slant_grey);
}

}  // namespace
}  // namespace ris
