#include "ris/io/ellipsoidal_dem.h"
#include "build_paths.h"

#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "ris/io/gdal_util.h"
#include "ris/io/raster_io.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

std::string dem_path(const std::string& name) {
  return std::string(ris::test::test_data_dir()) + "/dem/" + name;
}

// Rome-30m-DEM.tif declares EGM96 heights (EPSG:4326+5773): PROJ adds the
// geoid undulation, 48.613 m at 42.0 N 12.5 E (gdaltransform -s_srs
// EPSG:4326+5773 -t_srs EPSG:4979 with Debian's egm96_15.gtx).
TEST(EllipsoidalDem, GeoidHeightsBecomeEllipsoidal) {
  const EllipsoidalDem dem = read_ellipsoidal_dem(dem_path("Rome-30m-DEM.tif"));
  EXPECT_EQ(dem.cols, 360);
  EXPECT_EQ(dem.rows, 360);
  EXPECT_NE(dem.vertical_note.find("EGM96"), std::string::npos) << dem.vertical_note;
  EXPECT_NEAR(dem.geoid_offset_mean_m, 48.6, 0.3);
  const RasterF64 raw = read_raster_f64(dem_path("Rome-30m-DEM.tif"));
  // The cell whose centre is nearest 42.0 N 12.5 E.
  const int c = static_cast<int>(
      std::lround((12.5 - raw.georef.geotransform[0]) / raw.georef.geotransform[1] - 0.5));
  const int r = static_cast<int>(
      std::lround((42.0 - raw.georef.geotransform[3]) / raw.georef.geotransform[5] - 0.5));
  EXPECT_NEAR(dem.at(r, c) - raw.data[static_cast<std::size_t>(r) * 360 + c], 48.613, 0.01);
}

TEST(EllipsoidalDem, NoVerticalDatumAndNoData) {
  const EllipsoidalDem dem = read_ellipsoidal_dem(dem_path("winnipeg_dem.tif"));
  EXPECT_NE(dem.vertical_note.find("no vertical datum"), std::string::npos);
  EXPECT_EQ(dem.geoid_offset_mean_m, 0.0);
  // Bilinear lookup at a cell centre returns the cell; outside: NaN.
  EXPECT_FLOAT_EQ(static_cast<float>(dem.height_at(dem.lat0_rad + 10 * dem.dlat_rad,
                                                   dem.lon0_rad + 20 * dem.dlon_rad)),
                  dem.at(10, 20));
  EXPECT_TRUE(std::isnan(dem.height_at(dem.lat0_rad - 1.0, dem.lon0_rad)));
}

// A window of the file (EllipsoidalDemFile::read) interpolates exactly as
// the whole DEM wherever it holds the four postings around a point: the
// same bits at points spread over the window's interior, the geoid offset
// of its postings the whole DEM's; summarise() gives the whole DEM's range
// and note, read in bands of any height.
TEST(EllipsoidalDem, WindowsInterpolateAsTheWholeDem) {
  for (const char* name : {"Rome-30m-DEM.tif", "winnipeg_dem.tif"}) {
    const EllipsoidalDemFile file(dem_path(name));
    const EllipsoidalDem whole = read_ellipsoidal_dem(dem_path(name));
    ASSERT_EQ(file.grid().rows, whole.rows) << name;
    EXPECT_TRUE(file.grid().height_m.empty()) << name;
    const EllipsoidalDem w = file.read(37, 101, 53, 77);
    EXPECT_EQ(w.row0, 37);
    EXPECT_EQ(w.col0, 53);
    EXPECT_EQ(w.rows, 101);
    EXPECT_EQ(w.cols, 77);
    EXPECT_EQ(w.all_rows(), whole.rows);
    EXPECT_EQ(w.all_cols(), whole.cols);
    int compared = 0;
    for (double fr = 38.0; fr < 37.0 + 100.0 - 1.0; fr += 3.37) {
      for (double fc = 54.0; fc < 53.0 + 76.0 - 1.0; fc += 2.91) {
        const double lat = whole.lat0_rad + fr * whole.dlat_rad;
        const double lon = whole.lon0_rad + fc * whole.dlon_rad;
        const double a = whole.height_at(lat, lon), b = w.height_at(lat, lon);
        EXPECT_TRUE(a == b || (std::isnan(a) && std::isnan(b))) << name << " " << fr << " " << fc;
        EXPECT_EQ(w.at(static_cast<int>(fr) - 37, static_cast<int>(fc) - 53),
                  whole.at(static_cast<int>(fr), static_cast<int>(fc)));
        ++compared;
      }
    }
    EXPECT_GT(compared, 500) << name;
    // Clipped to the grid.
    const EllipsoidalDem edge = file.read(whole.rows - 5, 50, -10, 30);
    EXPECT_EQ(edge.row0, whole.rows - 5);
    EXPECT_EQ(edge.rows, 5);
    EXPECT_EQ(edge.col0, 0);
    EXPECT_EQ(edge.cols, 20);
    float lo = INFINITY, hi = -INFINITY;
    for (float h : whole.height_m) {
      if (std::isfinite(h)) {
        lo = std::min(lo, h);
        hi = std::max(hi, h);
      }
    }
    for (int band : {1, 7, 256, 100000}) {
      const EllipsoidalDemSummary sum = file.summarise(band);
      EXPECT_EQ(sum.min_m, lo) << name << " " << band;
      EXPECT_EQ(sum.max_m, hi) << name << " " << band;
      EXPECT_EQ(sum.vertical_note, whole.vertical_note) << name << " " << band;
      EXPECT_EQ(sum.geoid_offset_mean_m, whole.geoid_offset_mean_m) << name << " " << band;
    }
  }
}

TEST(EllipsoidalDem, RefusesProjectedDems) {
  test::TempDir tmp;
  OGRSpatialReference utm;
  utm.importFromEPSG(32633);
  Georef g;
  g.geotransform = {300000.0, 30.0, 0.0, 4650000.0, 0.0, -30.0};
  g.crs_wkt = wkt_of(utm);
  std::vector<float> h(100, 10.0F);
  write_geotiff<float>(tmp / "utm.tif", h.data(), 10, 10, &g);
  try {
    read_ellipsoidal_dem(tmp / "utm.tif");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("EPSG:4326"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ris
