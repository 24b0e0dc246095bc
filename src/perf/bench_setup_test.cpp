#include "ris/perf/bench_setup.h"
#include "build_paths.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ris/sensor/radar_config.h"
#include "ris/sensor/track.h"
#include "ris/util/units.h"

namespace ris {
namespace {

TEST(BenchSetup, FractalSceneIsSeededWithReliefAndAllCategories) {
  const Scene a = make_bench_scene(64, 80, 10.0, 3);
  const Scene b = make_bench_scene(64, 80, 10.0, 3);
  const Scene c = make_bench_scene(64, 80, 10.0, 4);
  EXPECT_EQ(a.elevation_m, b.elevation_m);
  EXPECT_NE(a.elevation_m, c.elevation_m);
  const auto [lo, hi] = std::minmax_element(a.elevation_m.begin(), a.elevation_m.end());
  EXPECT_GE(*lo, 0.0f);
  EXPECT_GT(*hi - *lo, 5.0f);  // relief, not a plate (0.05 x 640 m = 32 m nominal)
  EXPECT_LE(*hi, 0.05f * 640.0f);
  for (std::uint16_t k : a.category) {
    EXPECT_GE(k, 1);
    EXPECT_LE(k, 10);
  }
}

TEST(BenchSetup, RadarSwathCoversTheSceneAtAnyHeading) {
  const Scene s = make_bench_scene(50, 70, 10.0, 1);
  const RadarParams base =
      load_radar(std::string(ris::test::data_dir()) + "/radars/seed-fig4-5.toml");
  for (double heading_deg : {0.0, 30.0, 90.0, 200.0}) {
    const RadarParams r = bench_radar(base, s, deg_to_rad(heading_deg));
    const Track t = resolve_track(r.track, s, "bench");
    for (int row : {0, s.rows - 1}) {
      for (int col : {0, s.cols - 1}) {
        const auto [x, y] = s.cell_centre(row, col);
        const double u = t.along_cross(x, y).second;
        const double h = s.elevation_m[s.index(row, col)];
        const double R = std::hypot(u, t.altitude_m - h);
        EXPECT_GT(R, r.near_slant_range_m) << heading_deg;
        EXPECT_LT(R, r.far_slant_range_m) << heading_deg;
      }
    }
  }
}

}  // namespace
}  // namespace ris
