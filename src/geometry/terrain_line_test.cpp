#include "ris/geometry/terrain_line.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/util/units.h"

namespace ris {
namespace {

// A plane z = 100 + 0.3 x - 0.2 y on a 30 x 40 grid of 2 m cells.
Scene plane_scene() {
  Scene s = Scene::flat(30, 40, 2.0, 0.0f, 1);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const auto [x, y] = s.cell_centre(r, c);
      s.elevation_m[s.index(r, c)] = static_cast<float>(100.0 + 0.3 * x - 0.2 * y);
      s.category[s.index(r, c)] = static_cast<std::uint16_t>(1 + (r * 7 + c) % 5);
    }
  return s;
}

struct Sampled {
  std::vector<float> h, gx, gy;
  std::vector<std::uint16_t> cat;
  std::vector<std::uint8_t> flags;
  explicit Sampled(int n)
      : h(static_cast<std::size_t>(n)),
        gx(h.size()),
        gy(h.size()),
        cat(h.size()),
        flags(h.size()) {}
  SampledTerrain out() { return {h.data(), gx.data(), gy.data(), cat.data(), flags.data()}; }
};

// The texels hold each cell's height (NaN without data), its slope exactly
// as surface_gradient (either kernel; the vectorised interior and the edges
// alike) and its category.
TEST(TerrainLine, TexelsHoldHeightSlopeAndCategoryAsTheSceneAndGradient) {
  for (int cols : {1, 2, 3, 9, 10, 17, 40}) {
    Scene s = plane_scene();
    s.cols = cols;
    s.elevation_m.resize(static_cast<std::size_t>(s.rows * cols));
    s.category.resize(s.elevation_m.size());
    s.valid.resize(s.elevation_m.size());
    for (std::size_t i = 0; i < s.size(); ++i) {
      s.elevation_m[i] = static_cast<float>(std::sin(0.37 * double(i)) * 50.0 + 0.1 * double(i));
      s.category[i] = static_cast<std::uint16_t>(i % 7);
      s.valid[i] = (i % 5 == 3) ? 0 : 1;
    }
    for (const SamplerKernel kernel : {SamplerKernel::portable, SamplerKernel::best}) {
      const TerrainTexels tex = terrain_texels(s, kernel);
      const SurfaceGradient grad = surface_gradient(s);
      for (std::size_t i = 0; i < s.size(); ++i) {
        const TerrainTexel& t = tex.texel[i];
        EXPECT_EQ(static_cast<std::uint16_t>(t.category), s.category[i]);
        if (!s.valid[i]) {
          EXPECT_TRUE(std::isnan(t.height_m) && std::isnan(t.dz_dx) && std::isnan(t.dz_dy)) << i;
          continue;
        }
        EXPECT_EQ(t.height_m, s.elevation_m[i]) << i;
        EXPECT_EQ(t.dz_dx, grad.dz_dx[i]) << "cols " << cols << " cell " << i;
        EXPECT_EQ(t.dz_dy, grad.dz_dy[i]) << "cols " << cols << " cell " << i;
      }
    }
  }
}

// The span is exactly the samples within the scene (GridLine::inside), for
// lines at many headings and offsets, including lines that miss the scene,
// start or end inside it, or run along a grid axis or an edge.
TEST(TerrainLine, InsideSamplesIsExactlyTheSamplesWithinTheScene) {
  const Scene s = plane_scene();
  int non_empty = 0, empty = 0;
  for (double heading_deg = 0.0; heading_deg < 360.0; heading_deg += 7.5) {
    const double dx = std::sin(deg_to_rad(heading_deg)), dy = std::cos(deg_to_rad(heading_deg));
    for (double x0 : {-30.0, 0.0, 1.0, 37.3, 80.0, 95.0}) {
      for (double y0 : {-20.0, 0.0, 29.9, 60.0, 75.0}) {
        for (double first_u : {0.5, -41.0}) {
          const GridLine line = grid_line(s, x0, y0, dx, dy, first_u, 1.0);
          const int samples = 130;
          const auto [begin, end] = inside_samples(line, s.rows, s.cols, samples);
          ASSERT_LE(begin, end);
          for (int j = 0; j < samples; ++j) {
            ASSERT_EQ(line.inside(j, s.rows, s.cols), j >= begin && j < end)
                << "heading " << heading_deg << " x0 " << x0 << " y0 " << y0 << " j " << j;
          }
          (begin < end ? non_empty : empty) += 1;
        }
      }
    }
  }
  EXPECT_GT(non_empty, 100);
  EXPECT_GT(empty, 100);
}

// On a plane the bilinear height is the plane's (to float rounding) and the
// slope its gradient away from the edges; the category is the nearest cell's;
// every sample equals the single-point sampler at the same point.
TEST(TerrainLine, SamplesAPlaneExactlyAndAgreesWithThePointSampler) {
  const Scene s = plane_scene();
  const TerrainTexels tex = terrain_texels(s);
  const SurfaceGradient grad = surface_gradient(s);
  // Sample 0 at (1, 59) m (the north-west corner), steps of 0.5 m (a
  // quarter cell) towards 120 degrees (east-south-east).
  const double lx = std::sin(deg_to_rad(120.0)), ly = std::cos(deg_to_rad(120.0));
  const GridLine line = grid_line(s, 1.0, 59.0, lx, ly, 0.0, 0.5);
  const int samples = 200;
  const auto [begin, end] = inside_samples(line, s.rows, s.cols, samples);
  ASSERT_EQ(begin, 0);
  ASSERT_GT(end, 100);
  Sampled out(end - begin);
  sample_terrain_line(tex, line, begin, end, out.out());
  for (int j = begin; j < end; ++j) {
    const auto o = static_cast<std::size_t>(j - begin);
    const double x = 1.0 + 0.5 * j * lx, y = 59.0 + 0.5 * j * ly;
    ASSERT_EQ(out.flags[o], 0);
    const TerrainSample ts = bilinear_terrain_sample(s, &grad, x, y);
    ASSERT_TRUE(ts.valid);
    EXPECT_NEAR(out.h[o], ts.height_m, 1e-4) << j;
    EXPECT_NEAR(out.gx[o], ts.dz_dx, 1e-6) << j;
    EXPECT_NEAR(out.gy[o], ts.dz_dy, 1e-6) << j;
    // Between the outermost cell centres the plane is exact.
    const auto [cf, rf] = s.grid_from_world(x, y);
    if (cf > 0.5 && cf < s.cols - 0.5 && rf > 0.5 && rf < s.rows - 0.5) {
      EXPECT_NEAR(out.h[o], 100.0 + 0.3 * x - 0.2 * y, 2e-4) << j;
      EXPECT_NEAR(out.gx[o], 0.3, 1e-5) << j;
      EXPECT_NEAR(out.gy[o], -0.2, 1e-5) << j;
    }
    // The nearest cell contains the line's position (the point sampler's
    // position may differ in the last bit: compared away from cell edges).
    const int rn = std::min(static_cast<int>(line.row(j)), s.rows - 1);
    const int cn = std::min(static_cast<int>(line.col(j)), s.cols - 1);
    EXPECT_EQ(out.cat[o], s.category[s.index(rn, cn)]) << j;
    const auto near_edge = [](double v) { return std::abs(v - std::round(v)) < 1e-9; };
    if (!near_edge(cf) && !near_edge(rf)) {
      EXPECT_EQ(ts.category, out.cat[o]) << j;
    }
  }
}

// A sample touches no data when a cell it weights above 0 has none: on the
// no-data cell's centre row and column lines the cells beside it weigh 0.
TEST(TerrainLine, NoDataOnlyWhereANoDataCellIsWeighted) {
  Scene s = Scene::flat(10, 10, 1.0, 5.0f, 3);
  s.valid[s.index(4, 6)] = 0;
  s.elevation_m[s.index(4, 6)] = std::nanf("");
  const TerrainTexels tex = terrain_texels(s);
  // A line along row 3's centres (grid row 3.5), eastwards, quarter-cell
  // steps: it weighs row 4 by 0, so it never touches the no-data cell.
  const auto [x0, y0] = s.world_from_grid(0.0, 3.5);
  GridLine along = grid_line(s, x0, y0, 1.0, 0.0, 0.0, 0.25);
  auto [b0, e0] = inside_samples(along, s.rows, s.cols, 41);
  ASSERT_EQ(b0, 0);
  ASSERT_EQ(e0, 41);
  Sampled a(41);
  sample_terrain_line(tex, along, b0, e0, a.out());
  for (int j = 0; j < 41; ++j) {
    EXPECT_EQ(a.flags[static_cast<std::size_t>(j)], 0) << j;
    EXPECT_FLOAT_EQ(a.h[static_cast<std::size_t>(j)], 5.0f) << j;
  }
  // Along grid row 4.2 the no-data cell (row 4, column 6, centre 6.5) is
  // weighted from column 5.5 to 7.5 exclusive: samples at columns 5.75 ..
  // 7.25 have no data (NaN, category 0), the others are flat ground.
  const auto [x1, y1] = s.world_from_grid(0.0, 4.2);
  GridLine across = grid_line(s, x1, y1, 1.0, 0.0, 0.0, 0.25);
  Sampled b(41);
  sample_terrain_line(tex, across, 0, 41, b.out());
  for (int j = 0; j < 41; ++j) {
    const auto o = static_cast<std::size_t>(j);
    const double col = 0.25 * j;
    const bool touches = col > 5.5 && col < 7.5;
    EXPECT_EQ(b.flags[o], touches ? sample_flag::kNoData : 0) << col;
    EXPECT_EQ(std::isnan(b.h[o]), touches) << col;
    EXPECT_EQ(std::isnan(b.gx[o]), touches) << col;
    EXPECT_EQ(b.cat[o], touches ? 0 : 3) << col;
  }
}

// A rough surface on 41 x 57 cells of 1.5 m, categories 1-9, and a patch and
// a few single cells without data.
Scene rough_scene() {
  Scene s = Scene::flat(41, 57, 1.5, 0.0f, 1);
  for (int r = 0; r < s.rows; ++r)
    for (int c = 0; c < s.cols; ++c) {
      const std::size_t i = s.index(r, c);
      s.elevation_m[i] = static_cast<float>(50.0 + 7.0 * std::sin(0.37 * r + 0.11 * c * c) -
                                            3.0 * std::cos(0.21 * r * c) + 0.05 * (c - r));
      s.category[i] = static_cast<std::uint16_t>(1 + (r * 13 + c * 5) % 9);
      const bool patch = r >= 17 && r < 21 && c >= 30 && c < 35;
      if (patch || (r * 31 + c * 17) % 97 == 0) {
        s.valid[i] = 0;
        s.elevation_m[i] = std::nanf("");
      }
    }
  return s;
}

// One sample by the rule written out: bilinear_cells' corners and weights,
// then the weighted texels summed in float in corner order over the corners
// weighted above 0; no data (NaN, category 0) when a weighted corner has
// none.
void reference_sample(const TerrainTexels& tex, const GridLine& line, int j, float out[3],
                      std::uint16_t& category, std::uint8_t& flags) {
  const auto b = bilinear_cells<std::size_t>(tex.rows, tex.cols, line.col(j), line.row(j));
  const std::size_t corner[4] = {b.cell00, b.cell00 + b.step_col, b.cell00 + b.step_row,
                                 b.cell00 + b.step_row + b.step_col};
  float acc[3] = {0.0f, 0.0f, 0.0f};
  for (int k = 0; k < 4; ++k) {
    const TerrainTexel& t = tex.texel[corner[k]];
    const float w = b.weight[k];
    const float value[3] = {t.height_m, t.dz_dx, t.dz_dy};
    for (int v = 0; v < 3; ++v) acc[v] += w > 0.0f ? w * value[v] : 0.0f;
  }
  const bool no_data = std::isnan(acc[0]);
  for (int v = 0; v < 3; ++v) out[v] = acc[v];
  category = no_data ? 0 : static_cast<std::uint16_t>(tex.texel[b.nearest].category);
  flags = no_data ? sample_flag::kNoData : 0;
}

std::uint32_t bits(float f) {
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

// The line sampler (its best kernel on this CPU: AVX-512, AVX2 or SSE2, the
// chunks' vector bodies and their scalar ends; and its portable one) gives
// the rule's bits exactly on every sample: lines at 40 headings, with steps of a
// half and a third of a cell and lengths that end anywhere in a chunk, lines
// through cell centres and edges, no-data cells.
TEST(TerrainLine, SamplerGivesThePerSampleRuleBitForBit) {
  const Scene s = rough_scene();
  const TerrainTexels tex = terrain_texels(s);
  int compared = 0, no_data = 0;
  const auto check = [&](const GridLine& line, int samples) {
    const auto [begin, end] = inside_samples(line, s.rows, s.cols, samples);
    Sampled portable(std::max(end - begin, 1));
    sample_terrain_line(tex, line, begin, end, portable.out(), SamplerKernel::portable);
    Sampled out(std::max(end - begin, 1));
    sample_terrain_line(tex, line, begin, end, out.out());
    for (int j = begin; j < end; ++j) {
      const auto o = static_cast<std::size_t>(j - begin);
      float want[3];
      std::uint16_t cat = 0;
      std::uint8_t flags = 0;
      reference_sample(tex, line, j, want, cat, flags);
      ASSERT_EQ(bits(out.h[o]), bits(want[0])) << j;
      ASSERT_EQ(bits(out.gx[o]), bits(want[1])) << j;
      ASSERT_EQ(bits(out.gy[o]), bits(want[2])) << j;
      ASSERT_EQ(out.cat[o], cat) << j;
      ASSERT_EQ(out.flags[o], flags) << j;
      ASSERT_EQ(bits(portable.h[o]), bits(want[0])) << j;
      ASSERT_EQ(bits(portable.gx[o]), bits(want[1])) << j;
      ASSERT_EQ(bits(portable.gy[o]), bits(want[2])) << j;
      ASSERT_EQ(portable.cat[o], cat) << j;
      ASSERT_EQ(portable.flags[o], flags) << j;
      ++compared;
      no_data += flags != 0;
    }
  };
  for (int h = 0; h < 40; ++h) {
    const double heading = deg_to_rad(9.0 * h + 0.3);
    const double dx = std::sin(heading), dy = std::cos(heading);
    for (double step_m : {0.75, 0.5}) {
      // From west of the scene's centre, backwards first: the line crosses
      // the whole scene; its length varies with the heading.
      const GridLine line = grid_line(s, 40.0, 30.0, dx, dy, -60.0 - h, step_m);
      check(line, 240 + 7 * h);
    }
  }
  // Along cell centres and cell edges (weights of exactly 0 and 1/2, samples
  // on the edge between two cells), east and south.
  for (double r : {0.5, 3.0, 17.5, 19.0}) {
    const auto [x0, y0] = s.world_from_grid(0.0, r);
    check(grid_line(s, x0, y0, 1.0, 0.0, 0.0, 0.75), 200);
  }
  for (double c : {1.0, 31.5, 56.0}) {
    const auto [x0, y0] = s.world_from_grid(c, 0.0);
    check(grid_line(s, x0, y0, 0.0, -1.0, 0.0, 0.375), 200);
  }
  EXPECT_GT(compared, 10000);
  EXPECT_GT(no_data, 100);
}

}  // namespace
}  // namespace ris
