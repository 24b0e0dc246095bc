#include "ris/image/shadow_map.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "ris/util/units.h"
#include "slar_fixtures.h"

namespace ris {
namespace {

constexpr double kCell = 6.0, kH = 3000.0, kNear = 4000.0;

SlarImagingParams params(double near_m, int bins) {
  SlarImagingParams p;
  p.range = {near_m, kSpeedOfLight_m_per_s * 1e-7 / 2.0, bins};
  p.transmit_power_w = 1000.0;
  p.wavelength_m = 0.03;
  p.azimuth_beamwidth_rad = 0.006;
  return p;
}

std::vector<std::string> rows_of(const std::string& text) {
  std::vector<std::string> rows;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) rows.push_back(line);
  return rows;
}

TEST(ShadowMap, CharactersFollowTheSeedsCode) {
  EXPECT_EQ(shadow_map_char(0, 0), '9');
  EXPECT_EQ(shadow_map_char(3, 0), '0');
  EXPECT_EQ(shadow_map_char(3, 3), '3');
  EXPECT_EQ(shadow_map_char(9, 8), '8');
  EXPECT_EQ(shadow_map_char(12, 9), '#');
}

TEST(ShadowMap, FlatPlaneCountsEqualTheCellsWhoseSlantRangeFallsInEachBin) {
  // Swath wider than the scene on both sides: '9' beyond it.
  const Scene s = Scene::flat(5, 300, kCell, 0.0f, 1);
  const SlarImagingParams p = params(4800.0, 150);
  const SlarGeometry g = compute_slar_geometry(s, test::north_track(s, kH, kNear), 0.0, "r");
  const std::vector<std::string> rows =
      rows_of(shadow_map_text(form_slar_image(g, test::cosine_lut(s), p, "r")));
  ASSERT_EQ(rows.size(), 5u);
  std::string expected(150, '9');
  std::vector<int> count(150, 0);
  for (int c = 0; c < s.cols; ++c) {
    const double pos = (std::hypot(kNear + (c + 0.5) * kCell, kH) - p.range.near_m) / p.range.bin_m;
    if (pos >= 0 && pos < 150) ++count[static_cast<std::size_t>(pos)];
  }
  for (std::size_t b = 0; b < 150; ++b)
    if (count[b] > 0) expected[b] = shadow_map_char(count[b], count[b]);
  for (const std::string& row : rows) EXPECT_EQ(row, expected);
  EXPECT_EQ(expected.front(), '9');
  EXPECT_EQ(expected.back(), '9');
  EXPECT_NE(expected.find('3'), std::string::npos);
}

TEST(ShadowMap, BoxShowsShadowZerosAndLayoverCountsAboveFlatWhereTheGeometryPutsThem) {
  Scene s = Scene::flat(4, 300, kCell, 0.0f, 1);
  const double h = 200.0;
  for (int r = 0; r < s.rows; ++r)
    for (int c = 100; c < 120; ++c) s.elevation_m[s.index(r, c)] = float(h);
  const Scene flat = Scene::flat(4, 300, kCell, 0.0f, 1);
  const SlarImagingParams p = params(5000.0, 120);
  const auto text = [&](const Scene& sc) {
    const SlarGeometry g = compute_slar_geometry(sc, test::north_track(sc, kH, kNear), 0.0, "r");
    return rows_of(shadow_map_text(form_slar_image(g, test::cosine_lut(sc), p, "r")))[2];
  };
  const std::string box = text(s), ref = text(flat);
  EXPECT_EQ(ref.find('0'), std::string::npos);
  const auto bin_of = [&](double u, double z) {
    return static_cast<int>(std::floor((std::hypot(u, kH - z) - p.range.near_m) / p.range.bin_m));
  };
  const auto u_of = [](int c) { return kNear + (c + 0.5) * kCell; };
  // Shadow: the ground behind the box's far top sample (u_top, cell 119)
  // out to u_top H / (H - h), where the ray over the top meets the ground.
  const double u_top = u_of(119), u_end = u_top * kH / (kH - h);
  const int first_zero = static_cast<int>(box.find('0'));
  const int last_zero = static_cast<int>(box.rfind('0'));
  ASSERT_GE(first_zero, 0) << box;
  EXPECT_NEAR(first_zero, bin_of(u_top + kCell, 0.0), 1) << box;
  EXPECT_NEAR(last_zero, bin_of(u_end, 0.0), 1) << box;
  for (int b = first_zero; b <= last_zero; ++b) EXPECT_EQ(box[b], '0') << "bin " << b;
  // Layover: the top (cells 100-119 at h) lands among the nearer ground's
  // bins, which then count more points than flat ground does; nowhere else.
  const int top_near = bin_of(u_of(100), h), top_far = bin_of(u_of(119), h);
  int above = 0;
  for (int b = 0; b < static_cast<int>(box.size()); ++b) {
    if (box[b] == '0' || box[b] == '9' || !(box[b] == '#' || box[b] > ref[b])) continue;
    ++above;
    EXPECT_GE(b, top_near - 1) << box;
    EXPECT_LE(b, top_far + 1) << box;
  }
  EXPECT_GE(above, top_far - top_near - 1) << box;
}

}  // namespace
}  // namespace ris
