// Resampling error of tracks off the grid axes with land-cover patches
// (MODEL.md section 2, "Tracks that are not along a grid axis": a scene and
// a track rotated together give the same image, up to resampling error).
// SlarImage.SceneAndTrackRotatedTogetherBy30DegreesGiveTheSameImage checks
// smooth relief of one category; here the categories change every 60 m (10
// cells), so the error is that of the nearest-cell categories: the rotated
// scene's own grid (its cells' centres take the patch they fall in) and the
// half-cell sampling along each line.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "ris/geometry/slar_geometry.h"
#include "ris/image/slar_image.h"
#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

constexpr double kCell = 6.0;
constexpr double kH = 3000.0;
constexpr double kPatch = 60.0;

SlarImagingParams imaging_params() {
  SlarImagingParams p;
  p.range.near_m = 5130.0;  // 36 bins over u in about [4150, 4700]
  p.range.bin_m = kSpeedOfLight_m_per_s * 1e-7 / 2.0;
  p.range.count = 36;
  p.transmit_power_w = 1000.0;
  p.wavelength_m = kSpeedOfLight_m_per_s / 8.6e9;
  p.peak_gain = 300.0;
  p.azimuth_beamwidth_rad = 0.006;
  p.elevation_gain = [](double beta) { return std::exp(-std::pow((beta - 1.1) / 0.4, 2)); };
  return p;
}

// Category 0-5 (backscatter 0.05-0.3 x cos theta, test::CosineSigma0Source)
// of the kPatch-square patch containing track-frame point (s, u): a hash,
// so neighbouring patches differ irregularly.
std::uint16_t patch_category(double s_m, double u_m) {
  const auto a =
      static_cast<std::uint32_t>(static_cast<std::int64_t>(std::floor(s_m / kPatch)) + 100000);
  const auto b =
      static_cast<std::uint32_t>(static_cast<std::int64_t>(std::floor(u_m / kPatch)) + 100000);
  std::uint32_t h = (a * 2654435761u) ^ (b * 40503u + 0x9e3779b9u);
  h ^= h >> 13;
  h *= 0x5bd1e995u;
  h ^= h >> 15;
  return static_cast<std::uint16_t>(h % 6);
}

SlarImage patch_image(double heading_deg) {
  // A flat grid covering track-frame s in [0, 600], u in [3900, 4900], each
  // cell taking the patch of its centre.
  const Track t = test::endpoint_track(deg_to_rad(heading_deg), 600.0, kH);
  const Scene s = test::track_frame_scene(t, 600.0, 3900.0, 4900.0, kCell, 0,
                                          [](Scene& sc, std::size_t i, double s_m, double u_m) {
                                            sc.category[i] = patch_category(s_m, u_m);
                                          });
  const SlarGeometry g = compute_slar_geometry(s, t, kCell, "radar.toml");
  return form_slar_image(g, test::cosine_lut(s), imaging_params(), "radar.toml");
}

// Measured (2026-11-22): total 0.99957 and pixel error 0.92% at 30 deg,
// 0.99745 and 1.24% at 45 deg. Sampling each line at one cell instead of
// half (not used; docs/oblique-tracks.md) gave 0.99962 / 1.27% and 0.99854
// / 0.80%.
TEST(ObliqueResampling, LandCoverPatchesRotatedWithTheTrackGiveTheSameImage) {
  const SlarImage a = patch_image(0.0);
  for (double heading_deg : {30.0, 45.0}) {
    const SlarImage b = patch_image(heading_deg);
    ASSERT_EQ(a.lines, b.lines);
    ASSERT_EQ(a.bins, b.bins);
    const test::ImageAgreement d = test::image_agreement(a, b, 10);
    EXPECT_NEAR(d.relative_total, 1.0, 0.005) << heading_deg;
    EXPECT_LT(d.pixel_error, 0.02) << heading_deg;  // pixel-wise, relative to the total
    const std::string h = std::to_string(static_cast<int>(heading_deg));
    RecordProperty("relative_total_" + h, std::to_string(d.relative_total));
    RecordProperty("pixel_error_" + h, std::to_string(d.pixel_error));
  }
}

}  // namespace
}  // namespace ris
