#include "ris/image/slar_image.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>

#include "ris/util/error.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

using test::CosineSigma0Source;

constexpr double kCell = 6.0;
constexpr double kH = 3000.0;
constexpr double kNear = 4000.0;

double gaussian_gain(double beta) {
  return std::exp(-std::pow((beta - 1.1) / 0.4, 2));
}

SlarImagingParams test_params(double near_m = 5300.0, int bins = 200) {
  SlarImagingParams p;
  p.range.near_m = near_m;
  p.range.bin_m = kSpeedOfLight_m_per_s * 1e-7 / 2.0;  // c tau / 2
  p.range.count = bins;
  p.transmit_power_w = 1000.0;
  p.wavelength_m = kSpeedOfLight_m_per_s / 8.6e9;
  p.peak_gain = 300.0;
  p.azimuth_beamwidth_rad = 0.006;
  p.elevation_gain = gaussian_gain;
  return p;
}

TEST(SlarImage, FlatPlanePixelPowerFollowsTheRadarEquationAcrossTheSwath) {
  const Scene s = Scene::flat(120, 700, kCell, 0.0f, 2);
  const SlarGeometry g =
      compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "radar.toml");
  const SlarImagingParams p = test_params();
  const SlarImage img = form_slar_image(g, test::cosine_lut(s), p, "radar.toml");
  ASSERT_EQ(img.lines, 120);
  ASSERT_EQ(img.bins, 200);
  const double k_radar = p.transmit_power_w * p.wavelength_m * p.wavelength_m * p.peak_gain *
                         p.peak_gain / std::pow(4 * kPi, 3);
  double worst = 0.0, worst_area = 0.0;
  for (int line : {40, 60, 80}) {
    for (int b = 0; b < img.bins; ++b) {
      const double R = p.range.centre_m(b);
      const double u = std::sqrt(R * R - kH * kH);
      const double theta = std::atan2(u, kH);
      const double G = gaussian_gain(theta);
      // sigma0(theta) w(R) c tau / (2 sin theta) G^2 / R^4, times P_t lambda^2 / (4 pi)^3.
      const double expected = k_radar * CosineSigma0Source::gamma(2) * std::cos(theta) *
                              (R * p.azimuth_beamwidth_rad) * p.range.bin_m / std::sin(theta) * G *
                              G / std::pow(R, 4);
      const double got = img.mean_power_w[img.index(line, b)];
      const double rel = std::abs(got / expected - 1.0);
      worst = std::max(worst, rel);
      // Measured 1.7e-4 (the elements' ranges and angles spread over a bin,
      // against the bin centre's): the tolerance is 3 times that.
      EXPECT_LT(rel, 5e-4) << "line " << line << " bin " << b;
      EXPECT_EQ(img.mask[img.index(line, b)], 0);
      // The seed's cell area dA = w l, l = c tau / (2 sin theta).
      const double cell_area = R * p.azimuth_beamwidth_rad * p.range.bin_m / std::sin(theta);
      const double area_rel = std::abs(img.area_m2[img.index(line, b)] / cell_area - 1.0);
      worst_area = std::max(worst_area, area_rel);
      EXPECT_LT(area_rel, 2e-4);  // measured 4.1e-5
    }
  }
  RecordProperty("worst_relative_error", std::to_string(worst));
  RecordProperty("worst_area_error", std::to_string(worst_area));
  // Near the track's ends the footprint runs off the scene: less power.
  EXPECT_LT(img.mean_power_w[img.index(0, 100)], 0.8 * img.mean_power_w[img.index(60, 100)]);
}

TEST(SlarImage, CentreCountsEqualTheCellsWhoseSlantRangeFallsInEachBin) {
  const Scene s = Scene::flat(10, 700, kCell, 0.0f, 1);
  const SlarGeometry g =
      compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "radar.toml");
  const SlarImagingParams p = test_params();
  const SlarImage img = form_slar_image(g, test::cosine_lut(s), p, "radar.toml");
  std::vector<int> expected(static_cast<std::size_t>(img.bins), 0);
  for (int c = 0; c < s.cols; ++c) {
    const double u = kNear + (c + 0.5) * kCell;
    const double pos = (std::hypot(u, kH) - p.range.near_m) / p.range.bin_m;
    if (pos >= 0 && pos < img.bins) ++expected[static_cast<std::size_t>(pos)];
  }
  for (int b = 0; b < img.bins; ++b) {
    EXPECT_EQ(img.mapped_count[img.index(4, b)], expected[static_cast<std::size_t>(b)]) << b;
    EXPECT_EQ(img.visible_count[img.index(4, b)], expected[static_cast<std::size_t>(b)]) << b;
  }
}

TEST(SlarImage, TowerTopLaysOverTowardsNearRangeByThePredictedBins) {
  Scene s = Scene::flat(30, 700, kCell, 0.0f, 1);
  const int tower_row = 15, tower_col = 300;
  const float h = 400.0f;
  s.elevation_m[s.index(tower_row, tower_col)] = h;
  const SlarGeometry g =
      compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "radar.toml");
  const SlarImagingParams p = test_params();
  const SlarImage img = form_slar_image(g, test::cosine_lut(s), p, "radar.toml");
  const int line = s.rows - 1 - tower_row;  // track starts at the south edge
  const double u = kNear + (tower_col + 0.5) * kCell;
  const int base_bin = static_cast<int>((std::hypot(u, kH) - p.range.near_m) / p.range.bin_m);
  const int top_bin = static_cast<int>((std::hypot(u, kH - h) - p.range.near_m) / p.range.bin_m);
  const int predicted_shift =
      static_cast<int>(std::round((std::hypot(u, kH) - std::hypot(u, kH - h)) / p.range.bin_m));
  ASSERT_GE(predicted_shift, 5);
  EXPECT_NEAR(base_bin - top_bin, predicted_shift, 1);
  // The top is seen in its bin, on top of the flat ground there (one more
  // element than the neighbouring lines), and that pixel is flagged layover.
  const std::size_t top = img.index(line, top_bin);
  EXPECT_EQ(img.visible_count[top], img.visible_count[img.index(line - 3, top_bin)] + 1);
  EXPECT_TRUE(img.mask[top] & pixel_flag::kLayover);
  // No other bin of that line holds the top: every other bin matches the flat line.
  for (int b = 0; b < img.bins; ++b) {
    if (b == top_bin || std::abs(b - base_bin) <= 1) continue;
    EXPECT_EQ(img.mapped_count[img.index(line, b)], img.mapped_count[img.index(line - 3, b)]) << b;
  }
}

TEST(SlarImage, BoxLayoverPixelsSpanTheGeometricSlantRangeExtent) {
  Scene s = Scene::flat(40, 700, kCell, 0.0f, 1);
  const int c1 = 300, c2 = 330;
  const float h = 200.0f;
  for (int r = 0; r < s.rows; ++r)
    for (int c = c1; c < c2; ++c) s.elevation_m[s.index(r, c)] = h;
  const SlarGeometry g =
      compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "radar.toml");
  const SlarImagingParams p = test_params();
  const SlarImage img = form_slar_image(g, test::cosine_lut(s), p, "radar.toml");
  // Layover from the top's near edge to the ground at the same range.
  const double r_top = std::hypot(kNear + (c1 + 0.5) * kCell, kH - h);
  const double r_ground = std::hypot(kNear + (c1 - 0.5) * kCell, kH);
  int first = -1, last = -1;
  for (int b = 0; b < img.bins; ++b) {
    if (!(img.mask[img.index(20, b)] & pixel_flag::kLayover)) continue;
    if (first < 0) first = b;
    last = b;
  }
  const double extent_m = (last - first + 1) * p.range.bin_m;
  // Whole bins cover the extent plus at most one bin at each end (partial
  // bins and the elements' own range extent).
  EXPECT_GE(extent_m, r_ground - r_top);
  EXPECT_LE(extent_m, r_ground - r_top + 2 * p.range.bin_m);
  EXPECT_EQ(first, static_cast<int>((r_top - p.range.near_m) / p.range.bin_m));
  // Behind the box: shadow pixels, and more of them than layover ones here.
  int shadow = 0;
  for (int b = 0; b < img.bins; ++b)
    shadow += (img.mask[img.index(20, b)] & pixel_flag::kShadow) ? 1 : 0;
  EXPECT_GT(shadow, 0);
}

TEST(SlarImage, IdenticalBytesWithOneAndTwoThreads) {
  Scene s = Scene::flat(64, 300, kCell, 0.0f, 1);
  for (std::size_t i = 0; i < s.size(); ++i) {
    s.elevation_m[i] = static_cast<float>(40.0 * std::sin(0.01 * double(i)) + 40.0);
    s.category[i] = static_cast<std::uint16_t>(i % 3);
  }
  const SlarGeometry g =
      compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "radar.toml");
  const SlarImagingParams p = test_params(5000.0, 120);
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const SlarImage a = form_slar_image(g, test::cosine_lut(s), p, "radar.toml");
  const SlarGeometry g1 =
      compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "radar.toml");
  omp_set_num_threads(2);
  const SlarImage b = form_slar_image(g, test::cosine_lut(s), p, "radar.toml");
  const SlarGeometry g2 =
      compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "radar.toml");
  omp_set_num_threads(saved);
  ASSERT_EQ(a.mean_power_w.size(), b.mean_power_w.size());
  EXPECT_EQ(std::memcmp(a.mean_power_w.data(), b.mean_power_w.data(), a.mean_power_w.size() * 4),
            0);
  EXPECT_EQ(a.mask, b.mask);
  EXPECT_EQ(g1.flags, g2.flags);
  EXPECT_EQ(
      std::memcmp(g1.slant_range_m.data(), g2.slant_range_m.data(), g1.slant_range_m.size() * 4),
      0);
}

// Terrain given in the track frame (s, u): a round hill on a plane.
float hill(double s_m, double u_m) {
  const double ds = s_m - 300.0, du = u_m - 4400.0;
  return static_cast<float>(120.0 * std::exp(-(ds * ds + du * du) / (2.0 * 70.0 * 70.0)));
}

// A north-up grid covering the track-frame rectangle s in [0, 600],
// u in [u0, u1] for the given track, with the hill at its track coordinates.
Scene hill_scene(const Track& t, double u0, double u1) {
  return test::track_frame_scene(
      t, 600.0, u0, u1, kCell, 1,
      [](Scene& sc, std::size_t i, double s_m, double u_m) { sc.elevation_m[i] = hill(s_m, u_m); });
}

Track endpoint_track(double heading_rad) {
  return test::endpoint_track(heading_rad, 600.0, kH);
}

TEST(SlarImage, SceneAndTrackRotatedTogetherBy30DegreesGiveTheSameImage) {
  const Track t0 = endpoint_track(0.0);
  const Track t30 = endpoint_track(deg_to_rad(30.0));
  const Scene s0 = hill_scene(t0, 3900.0, 4900.0);
  const Scene s30 = hill_scene(t30, 3900.0, 4900.0);
  const SlarGeometry g0 = compute_slar_geometry(s0, t0, kCell, "radar.toml");
  const SlarGeometry g30 = compute_slar_geometry(s30, t30, kCell, "radar.toml");
  ASSERT_TRUE(g0.direct_sampling);
  ASSERT_FALSE(g30.direct_sampling);
  // Bins over u in about [4150, 4700]: inside both scenes' rectangles.
  const SlarImagingParams p = test_params(5130.0, 36);
  const SlarImage a = form_slar_image(g0, test::cosine_lut(s0), p, "radar.toml");
  const SlarImage b = form_slar_image(g30, test::cosine_lut(s30), p, "radar.toml");
  ASSERT_EQ(a.lines, b.lines);
  const test::ImageAgreement d = test::image_agreement(a, b, 10);
  EXPECT_NEAR(d.relative_total, 1.0, 0.002);
  EXPECT_LT(d.pixel_error, 0.01);  // pixel-wise resampling error, relative to the total
  EXPECT_GT(d.same_mask, 0.97);
  RecordProperty("relative_total", std::to_string(d.relative_total));
  RecordProperty("pixel_error", std::to_string(d.pixel_error));
}

TEST(SlarImage, SwathMissingTheSceneIsAnInputError) {
  const Scene s = Scene::flat(10, 50, kCell, 0.0f, 1);
  const SlarGeometry g =
      compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "radar.toml");
  try {
    (void)form_slar_image(g, test::cosine_lut(s), test_params(20000.0, 50), "radar.toml");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "radar.toml");
    EXPECT_EQ(e.key(), "sweep_delay");
    EXPECT_NE(std::string(e.what()).find("misses the scene"), std::string::npos);
  }
}

TEST(SlarImage, CategoryWithoutBackscatterIsAnInputError) {
  Scene s = Scene::flat(10, 50, kCell, 0.0f, 1);
  s.category[s.index(3, 7)] = 9;
  // The LUT refuses to be built without category 9 ...
  const std::vector<std::uint16_t> cats{1, 9};
  EXPECT_THROW(
      Sigma0Lut::build(CosineSigma0Source({1}), RadarBand{8.6e9, Polarisation::HH}, cats, "b.toml"),
      InputError);
  // ... and image formation refuses a LUT that lacks it.
  const Sigma0Lut partial =
      Sigma0Lut::build(CosineSigma0Source({1}), RadarBand{8.6e9, Polarisation::HH},
                       std::vector<std::uint16_t>{1}, "b.toml");
  const SlarGeometry g =
      compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "radar.toml");
  EXPECT_THROW((void)form_slar_image(g, partial, test_params(5000.0, 50), "radar.toml"),
               InputError);
}

}  // namespace
}  // namespace ris
