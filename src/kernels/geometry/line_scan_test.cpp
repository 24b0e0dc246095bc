#include "ris/geometry/line_scan.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace ris {
namespace {

// look_line (single precision, vectorised) agrees with look_at (double, libm)
// to float rounding: slant range and area to 2e-7 relative, the angles to
// 1e-6 rad (the sigma0 table's step is 1.7e-4 rad), and the back-facing flag
// wherever cos(theta_l) is not within rounding of 0.
TEST(LineScan, LookLineMatchesLookAtToFloatRounding) {
  const int n = 4000;
  const double H = 12192.0, first_u = -300.0, step = 6.0;
  const double look_x = std::cos(0.3), look_y = -std::sin(0.3);
  std::vector<float> u(n), h(n), gx(n), gy(n);
  for (int j = 0; j < n; ++j) {
    u[j] = static_cast<float>(first_u + j * step);
    h[j] = static_cast<float>(800.0 * std::sin(0.01 * j) + 300.0 * std::cos(0.037 * j));
    gx[j] = static_cast<float>(1.5 * std::sin(0.05 * j));
    gy[j] = static_cast<float>(0.8 * std::cos(0.031 * j));
  }
  h[7] = gx[7] = gy[7] = std::numeric_limits<float>::quiet_NaN();  // no terrain
  std::vector<float> range(n), inc(n), local(n), area(n), dh(n);
  std::vector<std::uint8_t> flags(n, 0);
  look_line({n, u.data(), h.data(), gx.data(), gy.data()}, {H, look_x, look_y, 36.0},
            {range.data(), inc.data(), local.data(), area.data(), dh.data(), flags.data()});
  EXPECT_TRUE(std::isnan(range[7]) && std::isnan(local[7]) && std::isnan(area[7]));
  EXPECT_TRUE(std::isnan(inc[7]));
  EXPECT_EQ(flags[7], 0);
  int back = 0;
  for (int j = 0; j < n; ++j) {
    if (j == 7) continue;
    TerrainSample ts;
    ts.inside = ts.valid = true;
    ts.height_m = h[j];
    ts.dz_dx = gx[j];
    ts.dz_dy = gy[j];
    const SampleLook s = look_at(ts, u[j], H, look_x, look_y);
    EXPECT_NEAR(range[j], s.slant_range_m, 2e-7 * s.slant_range_m) << j;
    EXPECT_NEAR(area[j], 36.0 * s.normal_length, 2e-7 * 36.0 * s.normal_length) << j;
    EXPECT_NEAR(inc[j], s.incidence_rad, 1e-6) << j;
    EXPECT_NEAR(local[j], local_incidence_rad(s), 1e-6) << j;
    EXPECT_NEAR(dh[j], s.dh_du, 1e-6 * (1.0 + std::abs(s.dh_du))) << j;
    if (std::abs(s.cos_local) > 1e-5) {
      EXPECT_EQ((flags[j] & sample_flag::kBackFacing) != 0, s.cos_local <= 0.0) << j;
    }
    back += (flags[j] & sample_flag::kBackFacing) ? 1 : 0;
  }
  EXPECT_GT(back, 0) << "the test line has back-facing slopes";
}

// Element ends of a flat line: R at u -+ step/2 and the datum height, and the
// local slope's extrapolation where a neighbour has no data.
TEST(LineScan, ElementEndsOfAFlatLineAndAtAGap) {
  const int n = 5;
  const double H = 1000.0, first_u = 100.0, step = 10.0;
  std::vector<float> h(n, 0.0f), range(n), near_end(n), far_end(n), dh(n, 0.0f);
  std::vector<std::uint8_t> flags(n, 0);
  flags[2] = sample_flag::kNoData;
  h[2] = std::numeric_limits<float>::quiet_NaN();
  dh[3] = 0.1f;  // sample 3 tilts: its near end (no neighbour) follows the slope
  const LineSamples l{
      n,         first_u,     step, H, h.data(), range.data(), near_end.data(), far_end.data(),
      dh.data(), flags.data()};
  line_element_ends(l);
  EXPECT_NEAR(near_end[0], std::hypot(95.0, H), 1e-3);
  EXPECT_NEAR(far_end[4], std::hypot(145.0, H), 1e-3);
  EXPECT_TRUE(std::isnan(near_end[2]) && std::isnan(far_end[2]));
  EXPECT_NEAR(near_end[3], std::hypot(125.0, H + 0.5), 1e-3);  // h_near = -0.1 x 5 m
  EXPECT_NEAR(far_end[3], std::hypot(135.0, H), 1e-3);         // shares sample 4's mean
}

// Both kernels of line_element_ends give the same bytes (the AVX-512 one
// sixteen samples at a time, where the CPU has it): rough random lines with
// gaps of every length, lines of 1 to 40 samples (blocks and rests) and of
// 700, far from and near the sensor.
TEST(LineScan, ElementEndsKernelsGiveTheSameBytes) {
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  int compared = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const int n = trial < 40 ? trial + 1 : 700;
    const double H = 3000.0 + 9000.0 * uni(rng), first_u = 10.0 + 40000.0 * uni(rng);
    const double step = trial % 2 ? 3.048 : 6.1;
    std::vector<float> h(n), dh(n), range(n);
    std::vector<std::uint8_t> flags(n, 0);
    double z = 300.0;
    for (std::size_t j = 0; j < h.size(); ++j) {
      const double dz = 8.0 * (uni(rng) - 0.5);
      z += dz;
      h[j] = static_cast<float>(z);
      dh[j] = static_cast<float>(dz / step);
      if (uni(rng) < 0.08) flags[j] = uni(rng) < 0.5 ? sample_flag::kNoData : sample_flag::kUnseen;
      if (flags[j] == sample_flag::kNoData && uni(rng) < 0.5) h[j] = NAN;
    }
    std::vector<float> near_best(n), far_best(n), near_portable(n), far_portable(n);
    line_element_ends({n, first_u, step, H, h.data(), range.data(), near_best.data(),
                       far_best.data(), dh.data(), flags.data()},
                      ScanKernel::best);
    line_element_ends({n, first_u, step, H, h.data(), range.data(), near_portable.data(),
                       far_portable.data(), dh.data(), flags.data()},
                      ScanKernel::portable);
    ASSERT_EQ(std::memcmp(near_best.data(), near_portable.data(), sizeof(float) * h.size()), 0)
        << "trial " << trial;
    ASSERT_EQ(std::memcmp(far_best.data(), far_portable.data(), sizeof(float) * h.size()), 0)
        << "trial " << trial;
    compared += n;
  }
  EXPECT_GT(compared, 14000);
}

// The shadow scan through the running minimum of cot psi against the
// horizon's cross-product test (the definition: shadowed where a nearer
// sample's look angle is larger, D u_max - u D_max > 0), and the layover
// scans against their definition, on rough random lines: some terrain above
// the antenna (a PPI on a mast), gaps, samples behind the sensor unseen.
TEST(LineScan, ShadowAndLayoverMatchTheirDefinitions) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  int shadowed = 0, layover = 0;
  for (int trial = 0; trial < 30; ++trial) {
    // More than one of the scan's blocks of 256, and short lines (1 to 16
    // samples: the eight-sample vector blocks and the remainder).
    const int n = trial % 5 == 4 ? 1 + 3 * (trial / 5) : 700;
    const double H = trial % 3 == 0 ? 300.0 : 3000.0;  // the low antenna sees hills above it
    const double first_u = trial % 2 == 0 ? -35.0 : 5.0, step = 10.0;
    std::vector<float> h(n), range(n), near_end(n), far_end(n), dh(n, 0.0f);
    std::vector<std::uint8_t> flags(n, 0);
    double z = 0.0;
    for (int j = 0; j < n; ++j) {
      const auto k = static_cast<std::size_t>(j);
      z += 40.0 * (uni(rng) - 0.5) + (uni(rng) < 0.02 ? 300.0 : 0.0);
      h[k] = static_cast<float>(z);
      const double u = first_u + j * step;
      range[k] = static_cast<float>(std::hypot(u, H - z));
      if (uni(rng) < 0.03) flags[k] |= sample_flag::kNoData;
      if (!(u > 0.0)) flags[k] |= sample_flag::kUnseen;
    }
    std::vector<std::uint8_t> expected = flags;
    const auto skip = [&](int j) {
      return (flags[static_cast<std::size_t>(j)] & (sample_flag::kNoData | sample_flag::kUnseen)) !=
             0;
    };
    double u_max = 0.0, d_max = 0.0;
    bool any = false;
    float max_r = -1.0f;
    for (int j = 0; j < n; ++j) {
      if (skip(j)) continue;
      const auto k = static_cast<std::size_t>(j);
      const double u = first_u + j * step, d = H - double(h[k]);
      if (!any || d * u_max - u * d_max < 0.0) {
        u_max = u;
        d_max = d;
        any = true;
      } else if (d * u_max - u * d_max > 0.0) {
        expected[k] |= sample_flag::kShadow;
      }
      if (range[k] < max_r) expected[k] |= sample_flag::kLayover;
      max_r = std::max(max_r, range[k]);
    }
    float min_r = std::numeric_limits<float>::infinity();
    for (int j = n - 1; j >= 0; --j) {
      if (skip(j)) continue;
      const auto k = static_cast<std::size_t>(j);
      if (range[k] > min_r) expected[k] |= sample_flag::kLayover;
      min_r = std::min(min_r, range[k]);
    }
    // Both kernels (on a CPU without AVX-512 both run the portable one).
    for (const ScanKernel kernel : {ScanKernel::portable, ScanKernel::best}) {
      std::vector<std::uint8_t> got = flags;
      mark_shadow_and_layover({n, first_u, step, H, h.data(), range.data(), near_end.data(),
                               far_end.data(), dh.data(), got.data()},
                              kernel);
      EXPECT_EQ(got, expected) << "trial " << trial << " kernel " << static_cast<int>(kernel);
      if (kernel == ScanKernel::best) flags = got;
    }
    for (const std::uint8_t f : flags) {
      shadowed += (f & sample_flag::kShadow) ? 1 : 0;
      layover += (f & sample_flag::kLayover) ? 1 : 0;
    }
  }
  EXPECT_GT(shadowed, 1000);
  EXPECT_GT(layover, 100);
}

}  // namespace
}  // namespace ris
