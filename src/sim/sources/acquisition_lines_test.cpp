#include "sim/sources/acquisition_lines.h"

#include <gtest/gtest.h>

#include <cmath>

#include "acquisition_test_dems.h"
#include "ris/geometry/terrain_profile.h"
#include "sim/sources/acquisition_frame.h"

namespace ris::detail {
namespace {

// A streamed block's DEM window (dem_rect_of_lines) holds, with a posting
// to spare, the postings every profile point of its lines reads: the
// bilinear cell around it and the slope's neighbours one posting away
// (checked against trace_terrain_profile's own points, every point of
// every line); and a block of 4 lines reads about one line's box, less
// than the whole window's lines read.
TEST(AcquisitionLines, BlockDemWindowHoldsItsLinesPostings) {
  const Acquisition a = test::small_airborne();
  const EllipsoidalDem dem = test::dem_for(a, 300.0, 1500.0);
  const AcquisitionFrame f = acquisition_frame(a, dem, false);
  AcquisitionRun run{a,           dem,         f.window, EarthModel::ellipsoid, 1, nullptr,
                     f.dem_min_m, f.dem_max_m, 3};
  run.max_points = acquisition_max_points(run);
  const int lines = f.window.lines;
  ASSERT_GE(lines, 20);
  const DemRect all = dem_rect_of_lines(run, 0, lines);
  EXPECT_GT(all.rows, 0);
  int points = 0;
  for (const auto& [l0, l1] :
       {std::pair{0, 4}, std::pair{lines / 2, lines / 2 + 4}, std::pair{lines - 4, lines}}) {
    const DemRect part = dem_rect_of_lines(run, l0, l1);
    // About one line's box (the track is diagonal: a line's box is wide).
    const DemRect one = dem_rect_of_lines(run, l0, l0 + 1);
    EXPECT_LT(double(part.rows) * part.cols, 1.2 * double(one.rows) * one.cols) << l0;
    EXPECT_LT(double(part.rows) * part.cols, 0.9 * double(all.rows) * all.cols) << l0;
    EXPECT_GE(part.row0, all.row0);
    EXPECT_LE(part.row0 + part.rows, all.row0 + all.rows);
    TerrainProfile profile;
    for (int line = l0; line < l1; ++line) {
      const OrbitState st = a.orbit.interpolate(a.grid.time_of_line(f.window.line0 + line));
      const ZeroDopplerFrame zf(st, a.grid.look_side, a.ellipsoid);
      trace_terrain_profile(zf, a.ellipsoid, dem, run.span_of_line(zf), true, profile);
      for (std::size_t k = 0; k < profile.lat_rad.size(); ++k) {
        if (!std::isfinite(profile.height_m[k])) continue;  // off the DEM
        const double r = (profile.lat_rad[k] - dem.lat0_rad) / dem.dlat_rad;
        const double c = (profile.lon_rad[k] - dem.lon0_rad) / dem.dlon_rad;
        // Rows floor(r) - 1 .. floor(r) + 2 inside the grid, all held.
        const int r_lo = std::max(0, int(std::floor(r)) - 1);
        const int r_hi = std::min(dem.rows - 1, int(std::floor(r)) + 2);
        const int c_lo = std::max(0, int(std::floor(c)) - 1);
        const int c_hi = std::min(dem.cols - 1, int(std::floor(c)) + 2);
        ASSERT_GE(r_lo, part.row0) << line << " " << k;
        ASSERT_LT(r_hi, part.row0 + part.rows) << line << " " << k;
        ASSERT_GE(c_lo, part.col0) << line << " " << k;
        ASSERT_LT(c_hi, part.col0 + part.cols) << line << " " << k;
        ++points;
      }
    }
  }
  EXPECT_GT(points, 1000);
}

}  // namespace
}  // namespace ris::detail
