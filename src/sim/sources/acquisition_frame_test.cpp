#include "sim/sources/acquisition_frame.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "acquisition_test_dems.h"
#include "ris/util/error.h"

namespace ris::detail {
namespace {

TEST(AcquisitionFrame, HeightRangeSkipsNoData) {
  EllipsoidalDem d;
  d.rows = 1;
  d.cols = 4;
  d.source = "h.tif";
  const float nan = std::numeric_limits<float>::quiet_NaN();
  d.height_m = {nan, 12.5F, -3.0F, nan};
  const HeightRange h = dem_height_range(d);
  EXPECT_EQ(h.min_m, -3.0F);
  EXPECT_EQ(h.max_m, 12.5F);
  d.height_m = {nan, nan, nan, nan};
  try {
    dem_height_range(d);
    FAIL() << "a DEM without data was accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("h.tif"), std::string::npos) << err.what();
  }
}

// The window the DEM covers and the whole grid; the heights of a ridge DEM;
// the ground line spacing against the distance between the sensor's nadir
// points of two lines at the DEM's mid height (an independent path: the
// ellipsoid's chord, not the angular rate).
TEST(AcquisitionFrame, WindowHeightsAndGroundLineSpacing) {
  const Acquisition a = test::small_airborne();
  const EllipsoidalDem dem = test::dem_for(a, 300.0, 1500.0);
  const AcquisitionFrame f = acquisition_frame(a, dem, false);
  const GridWindow w = dem_window(a, dem);
  EXPECT_EQ(f.window.line0, w.line0);
  EXPECT_EQ(f.window.lines, w.lines);
  EXPECT_EQ(f.window.bin0, w.bin0);
  EXPECT_EQ(f.window.bins, w.bins);
  EXPECT_EQ(f.dem_min_m, 230.0F);
  EXPECT_LE(f.dem_max_m, 530.0F);
  EXPECT_GT(f.dem_max_m, 500.0F);  // 1 arc-second postings near a 1.5 km half-width crest

  const AcquisitionFrame full = acquisition_frame(a, dem, true);
  EXPECT_EQ(full.window.line0, 0);
  EXPECT_EQ(full.window.lines, a.grid.lines);
  EXPECT_EQ(full.window.bins, a.grid.bins);

  const double t_mid = a.grid.time_of_line(f.window.line0 + 0.5 * (f.window.lines - 1));
  const double dt = a.grid.line_interval_s;
  const double h_mid = 0.5 * (f.dem_min_m + f.dem_max_m);
  const auto nadir = [&](double t) {
    Geodetic g = a.ellipsoid.to_geodetic(a.orbit.interpolate(t).position_m);
    EXPECT_NEAR(g.height_m, f.sensor_height_m, 50.0);  // a level flight line
    g.height_m = h_mid;
    return a.ellipsoid.to_ecef(g);
  };
  const double chord_m = (nadir(t_mid + 0.5 * dt) - nadir(t_mid - 0.5 * dt)).norm();
  EXPECT_GT(f.ground_azimuth_spacing_m, 0.0);
  // 1e-4: the two paths agree to ~5e-6 here; leaving out the factor
  // terrain radius / sensor radius (altitude ~12 km) is off by ~2e-3.
  EXPECT_NEAR(f.ground_azimuth_spacing_m, chord_m, 1e-4 * chord_m);
}

TEST(AcquisitionFrame, DemOutsideTheGridIsRefusedNamingTheDem) {
  const Acquisition a = test::small_airborne();
  EllipsoidalDem dem = test::dem_for(a, 0.0, 1.0);
  dem.lat0_rad += deg_to_rad(5.0);  // five degrees north of the flight line
  dem.source = "far.tif";
  try {
    acquisition_frame(a, dem, false);
    FAIL() << "a DEM off the grid was accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("far.tif"), std::string::npos) << err.what();
  }
}

TEST(AcquisitionFrame, InMemoryWindowIsCappedAtFiftyMegapixels) {
  EXPECT_NO_THROW(check_in_memory_window(GridWindow{0, 5000, 0, 10000}, "a.h5", false));
  for (const bool full_grid : {false, true}) {
    try {
      check_in_memory_window(GridWindow{0, 5000, 0, 10001}, "a.h5", full_grid);
      FAIL() << "a window of 50,005,000 pixels was accepted";
    } catch (const InputError& err) {
      const std::string m = err.what();
      EXPECT_NE(m.find("a.h5"), std::string::npos) << m;
      EXPECT_NE(m.find(full_grid ? "--full-grid" : "--dem"), std::string::npos) << m;
      EXPECT_NE(m.find("5000 lines x 10001 bins"), std::string::npos) << m;
    }
  }
}

}  // namespace
}  // namespace ris::detail
