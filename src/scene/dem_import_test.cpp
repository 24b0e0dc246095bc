#include "ris/scene/dem_import.h"
#include "build_paths.h"

#include <cpl_string.h>
#include <fmt/format.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ris/io/gdal_util.h"
#include "ris/io/raster_io.h"
#include "ris/scene/geo_frame.h"
#include "ris/scene/scene_io.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

const std::string kDemDir = std::string(ris::test::test_data_dir()) + "/dem/";

std::string wkt_of_epsg(int code) {
  OGRSpatialReference srs;
  srs.importFromEPSG(code);
  char* text = nullptr;
  srs.exportToWkt(&text);
  std::string out = text;
  CPLFree(text);
  return out;
}

// Independent reference for the import: each scene cell centre is taken to
// latitude/longitude with PROJ (GeoFrame), then to the source grid.
struct SourceDem {
  RasterF64 raster;
  explicit SourceDem(const std::string& path) : raster(read_raster_f64(path)) {}
  double gt(int k) const { return raster.georef.geotransform[static_cast<std::size_t>(k)]; }
  // Fractional pixel coordinates (col, row) of a lon/lat; pixel centres at +0.5.
  std::pair<double, double> pixel(double lon, double lat) const {
    return {(lon - gt(0)) / gt(1), (lat - gt(3)) / gt(5)};
  }
  bool is_data(int c, int r) const {
    if (c < 0 || r < 0 || c >= raster.cols || r >= raster.rows) return false;
    const double v = raster.data[static_cast<std::size_t>(r) * raster.cols + c];
    return std::isfinite(v) && !(raster.nodata && v == *raster.nodata) && std::abs(v) < 1e30;
  }
  double at(int c, int r) const {
    return raster.data[static_cast<std::size_t>(r) * raster.cols + c];
  }
};

// No-data cells the import should produce: the posting nearest the centre is
// outside the DEM or no-data.
std::size_t expected_nodata(const Scene& s, const SourceDem& src) {
  GeoFrame frame(s.crs_wkt, "scene");
  std::size_t n = 0;
  for (int r = 0; r < s.rows; ++r) {
    for (int c = 0; c < s.cols; ++c) {
      auto [x, y] = s.cell_centre(r, c);
      auto [lon, lat] = frame.lonlat_from_scene(x, y);
      auto [pc, pr] = src.pixel(lon, lat);
      n += !src.is_data(static_cast<int>(std::floor(pc)), static_cast<int>(std::floor(pr)));
    }
  }
  return n;
}

struct RealDemCase {
  std::string file;
  int utm_zone;
  double cell_m;        // default cell size: 1 arc-second in metres, 2 digits
  double min_h, max_h;  // source height range (SOURCES.md, gdalinfo)
};

class RealDem : public ::testing::TestWithParam<RealDemCase> {};

TEST_P(RealDem, ImportsIntoUtmWithRightExtentHeightsAndNoData) {
  const RealDemCase& k = GetParam();
  const std::string path = kDemDir + k.file;
  ImportedDem dem = import_dem(path);
  const Scene& s = dem.scene;
  SourceDem src(path);

  // Frame: WGS 84 / UTM zone of the centre, square cells of the rounded posting.
  EXPECT_TRUE(dem.reprojected);
  EXPECT_EQ(dem.frame, fmt::format("WGS 84 / UTM zone {}N", k.utm_zone));
  EXPECT_EQ(dem.metadata.at("RIS_SOURCE_DEM"), k.file);
  EXPECT_DOUBLE_EQ(s.dx_m, k.cell_m);
  EXPECT_DOUBLE_EQ(s.dy_m, k.cell_m);
  EXPECT_DOUBLE_EQ(std::fmod(s.origin_x_m, k.cell_m), 0.0);  // aligned grid

  // Extent: the bounding box of the DEM's outline in UTM (PROJ on a densified
  // boundary), snapped outwards to whole cells.
  GeoFrame frame(s.crs_wkt, path);
  double min_x = 1e300, max_x = -1e300, min_y = 1e300, max_y = -1e300;
  const int n = 200;
  for (int i = 0; i <= n; ++i) {
    const double f = double(i) / n;
    const double lon0 = src.gt(0), lon1 = src.gt(0) + src.raster.cols * src.gt(1);
    const double lat0 = src.gt(3), lat1 = src.gt(3) + src.raster.rows * src.gt(5);
    for (auto [lon, lat] :
         {std::pair{lon0 + f * (lon1 - lon0), lat0}, std::pair{lon0 + f * (lon1 - lon0), lat1},
          std::pair{lon0, lat0 + f * (lat1 - lat0)}, std::pair{lon1, lat0 + f * (lat1 - lat0)}}) {
      auto [x, y] = frame.scene_from_lonlat(lon, lat);
      min_x = std::min(min_x, x);
      max_x = std::max(max_x, x);
      min_y = std::min(min_y, y);
      max_y = std::max(max_y, y);
    }
  }
  EXPECT_NEAR(s.origin_x_m, std::floor(min_x / k.cell_m) * k.cell_m, 1e-6);
  EXPECT_NEAR(s.origin_y_m, std::ceil(max_y / k.cell_m) * k.cell_m, 1e-6);
  EXPECT_NEAR(s.cols, std::ceil(max_x / k.cell_m) - std::floor(min_x / k.cell_m), 0.5);
  EXPECT_NEAR(s.rows, std::ceil(max_y / k.cell_m) - std::floor(min_y / k.cell_m), 0.5);

  // No-data: the corners of the UTM box outside the DEM, counted, and in the
  // metadata. Ties on posting edges may go either way: allow a few cells.
  const std::size_t expect = expected_nodata(s, src);
  EXPECT_GT(dem.nodata_cells, 0u);
  EXPECT_NEAR(double(dem.nodata_cells), double(expect), 5.0);
  EXPECT_EQ(dem.nodata_cells, count_nodata(s));
  EXPECT_EQ(dem.metadata.at("RIS_NODATA_CELLS"), std::to_string(dem.nodata_cells));

  // Heights inside the source range (as given: no geoid shift applied).
  float lo = std::numeric_limits<float>::max(), hi = -lo;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!s.valid[i]) continue;
    lo = std::min(lo, s.elevation_m[i]);
    hi = std::max(hi, s.elevation_m[i]);
  }
  EXPECT_GE(lo, k.min_h - 0.01);
  EXPECT_LE(hi, k.max_h + 0.01);

  // At cells finer than the postings, heights are the bilinear interpolation
  // of the postings (GDAL's pixel-centre convention). (At coarser cells GDAL
  // widens the kernel to average, which is what a coarser grid should do.)
  DemImportOptions fine_opt;
  fine_opt.cell_size_m = 15.0;
  const Scene fine = import_dem(path, fine_opt).scene;
  int checked = 0;
  for (int r = 0; r < fine.rows; r += 7) {
    for (int c = 0; c < fine.cols; c += 5) {
      if (!fine.valid[fine.index(r, c)]) continue;
      const float h = fine.elevation_m[fine.index(r, c)];
      auto [x, y] = fine.cell_centre(r, c);
      auto [lon, lat] = frame.lonlat_from_scene(x, y);
      auto [pc, pr] = src.pixel(lon, lat);
      const double u = pc - 0.5, v = pr - 0.5;
      const int c0 = static_cast<int>(std::floor(u)), r0 = static_cast<int>(std::floor(v));
      if (!src.is_data(c0, r0) || !src.is_data(c0 + 1, r0 + 1) || !src.is_data(c0 + 1, r0) ||
          !src.is_data(c0, r0 + 1)) {
        continue;
      }
      const double fu = u - c0, fv = v - r0;
      const double expect_h = (1 - fv) * ((1 - fu) * src.at(c0, r0) + fu * src.at(c0 + 1, r0)) +
                              fv * ((1 - fu) * src.at(c0, r0 + 1) + fu * src.at(c0 + 1, r0 + 1));
      ASSERT_NEAR(h, expect_h, 2e-3 + 1e-5 * std::abs(expect_h)) << r << "," << c;
      ++checked;
    }
  }
  EXPECT_GT(checked, 1000);
}

INSTANTIATE_TEST_SUITE_P(
    SharedDems, RealDem,
    ::testing::Values(RealDemCase{"Rome-30m-DEM.tif", 33, 27.0, 5.0, 115.0},
                      RealDemCase{"SanAnd_dem.tif", 11, 30.0, 149.279, 291.637},
                      RealDemCase{"dem_himalayas_E81p5_N28p3_short.tiff", 44, 28.0, 90.704,
                                  355.355},
                      RealDemCase{"winnipeg_dem.tif", 14, 25.0, 233.0, 257.0}),
    [](const auto& p) { return p.param.file.substr(0, p.param.file.find_first_of("-_.")); });

TEST(DemImport, VerticalDatumIsStatedAndDeclaredOneNamed) {
  ImportedDem rome = import_dem(kDemDir + "Rome-30m-DEM.tif");
  EXPECT_NE(rome.vertical_datum.find("EGM96"), std::string::npos) << rome.vertical_datum;
  ImportedDem sanand = import_dem(kDemDir + "SanAnd_dem.tif");
  EXPECT_NE(sanand.vertical_datum.find("as given by the DEM"), std::string::npos);
  EXPECT_EQ(sanand.metadata.at("RIS_VERTICAL_DATUM"), sanand.vertical_datum);
}

TEST(DemImport, NoDataHolesStayHolesAndAreCounted) {
  // San Andreas DEM with a 12 x 20 posting block of no-data punched in.
  test::TempDir dir;
  SourceDem src(kDemDir + "SanAnd_dem.tif");
  RasterF64 holed = src.raster;
  std::vector<float> data(holed.data.begin(), holed.data.end());
  for (int r = 100; r < 120; ++r)
    for (int c = 40; c < 52; ++c) data[static_cast<std::size_t>(r) * holed.cols + c] = -9999.0f;
  Georef g{holed.georef.geotransform, wkt_of_epsg(4326)};
  write_geotiff<float>(dir / "holed.tif", data.data(), holed.cols, holed.rows, &g, -9999.0);

  ImportedDem base = import_dem(kDemDir + "SanAnd_dem.tif");
  ImportedDem dem = import_dem(dir / "holed.tif");
  // The hole covers 12 x 20 postings of 1" (~25.6 m x 30.8 m at 34.2 N) in
  // 30 m cells: about 12*25.6 * 20*30.8 / 900 = 210 cells.
  const double hole_cells = double(dem.nodata_cells) - double(base.nodata_cells);
  EXPECT_NEAR(hole_cells, 12 * 25.6 * 20 * 30.8 / 900.0, 25.0);
  EXPECT_NEAR(double(dem.nodata_cells),
              double(expected_nodata(dem.scene, SourceDem(dir / "holed.tif"))), 5.0);
  // Every no-data cell reads back as no-data from the scene file.
  write_scene_geotiff(dem.scene, dir / "scene.tif", dem.metadata);
  Scene back = read_scene(dir / "scene.tif");
  EXPECT_EQ(count_nodata(back), dem.nodata_cells);
  RasterF64 file = read_raster_f64(dir / "scene.tif");
  EXPECT_EQ(file.metadata.at("RIS_NODATA_CELLS"), std::to_string(dem.nodata_cells));
  EXPECT_NE(file.metadata.at("RIS_FRAME").find("UTM zone 11N"), std::string::npos);
}

TEST(DemImport, DemWithoutCrsIsRefusedUnlessOneIsGiven) {
  test::TempDir dir;
  std::vector<float> h(20 * 10, 100.0f);
  Georef g{{12.0, 1.0 / 3600, 0, 42.0, 0, -1.0 / 3600}, ""};
  write_geotiff<float>(dir / "nocrs.tif", h.data(), 20, 10, &g);
  try {
    import_dem(dir / "nocrs.tif");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("nocrs.tif"), std::string::npos) << what;
    EXPECT_NE(what.find("no CRS"), std::string::npos) << what;
    EXPECT_NE(what.find("--crs"), std::string::npos) << what;
  }
  DemImportOptions opt;
  opt.crs = "EPSG:4326";
  ImportedDem dem = import_dem(dir / "nocrs.tif", opt);
  EXPECT_EQ(dem.frame, "WGS 84 / UTM zone 33N");
  opt.crs = "EPSG:999999";
  EXPECT_THROW(import_dem(dir / "nocrs.tif", opt), InputError);
}

TEST(DemImport, MetricDemKeepsItsGridOrIsResampledInItsCrs) {
  test::TempDir dir;
  const int cols = 40, rows = 30;
  std::vector<float> h(cols * rows);
  for (int i = 0; i < cols * rows; ++i) h[i] = float(i % cols) * 2.0f;  // slope east
  Georef g{{500000.0, 10.0, 0, 4200000.0, 0, -10.0}, wkt_of_epsg(32633)};
  write_geotiff<float>(dir / "utm.tif", h.data(), cols, rows, &g);
  ImportedDem same = import_dem(dir / "utm.tif");
  EXPECT_FALSE(same.reprojected);
  EXPECT_EQ(same.scene.cols, cols);
  EXPECT_DOUBLE_EQ(same.scene.origin_x_m, 500000.0);
  EXPECT_EQ(same.scene.elevation_m, h);
  EXPECT_EQ(same.nodata_cells, 0u);

  DemImportOptions opt;
  opt.cell_size_m = 20.0;
  ImportedDem coarse = import_dem(dir / "utm.tif", opt);
  EXPECT_TRUE(coarse.reprojected);
  EXPECT_EQ(coarse.frame, "WGS 84 / UTM zone 33N");
  EXPECT_EQ(coarse.scene.cols, cols / 2);
  EXPECT_EQ(coarse.scene.rows, rows / 2);
  // A 20 m cell centre lies midway between two 10 m postings: the slope's mean.
  EXPECT_NEAR(coarse.scene.elevation_m[coarse.scene.index(5, 5)], (10.5 - 0.5) * 2.0 + 1.0, 1e-4);
}

TEST(DemImport, TooLargeForMemoryIsRefusedWithTheEstimate) {
  DemImportOptions opt;
  opt.cell_size_m = 0.001;
  try {
    import_dem(kDemDir + "SanAnd_dem.tif", opt);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("GiB"), std::string::npos) << what;
    EXPECT_NE(what.find("--cell-size"), std::string::npos) << what;
  }
  opt.cell_size_m = -3.0;
  EXPECT_THROW(import_dem(kDemDir + "SanAnd_dem.tif", opt), InputError);
}

TEST(DemImport, SrtmHgtTileImports) {
  // A 3-arc-second SRTM tile written by GDAL's SRTMHGT driver.
  ensure_gdal_registered();
  test::TempDir dir;
  const int n = 1201;
  GdalDataset mem(GDALCreate(GDALGetDriverByName("MEM"), "", n, n, 1, GDT_Int16, nullptr));
  std::array<double, 6> gt{7.0 - 1.5 / 3600, 3.0 / 3600, 0, 46.0 + 1.5 / 3600, 0, -3.0 / 3600};
  GDALSetGeoTransform(handle(mem), gt.data());
  GDALSetProjection(handle(mem), wkt_of_epsg(4326).c_str());
  std::vector<std::int16_t> h(static_cast<std::size_t>(n) * n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) h[static_cast<std::size_t>(r) * n + c] = std::int16_t(500 + r / 4);
  for (int r = 600; r < 620; ++r)
    for (int c = 600; c < 620; ++c) h[static_cast<std::size_t>(r) * n + c] = -32768;
  GDALRasterBandH band = GDALGetRasterBand(handle(mem), 1);
  GDALSetRasterNoDataValue(band, -32768);
  ASSERT_EQ(GDALRasterIO(band, GF_Write, 0, 0, n, n, h.data(), n, n, GDT_Int16, 0, 0), CE_None);
  const std::string hgt = (dir / "N45E007.hgt").string();
  GdalDataset out(GDALCreateCopy(GDALGetDriverByName("SRTMHGT"), hgt.c_str(), handle(mem), FALSE,
                                 nullptr, nullptr, nullptr));
  ASSERT_TRUE(out) << last_gdal_error();
  out.reset();

  ImportedDem dem = import_dem(hgt);
  EXPECT_EQ(dem.frame, "WGS 84 / UTM zone 32N");
  EXPECT_NE(dem.vertical_datum.find("EGM96"), std::string::npos);
  // 3" is 92.6 m north-south, 65.5 m east-west at 45.5 N.
  EXPECT_GE(dem.scene.dx_m, 65.0);
  EXPECT_LE(dem.scene.dx_m, 93.0);
  // The 20 x 20 posting hole (~1310 m x 1852 m) is masked.
  auto [x, y] = GeoFrame(dem.scene.crs_wkt, hgt)
                    .scene_from_lonlat(7.0 + 610.0 * 3 / 3600, 46.0 - 610.0 * 3 / 3600);
  auto [c, r] = dem.scene.grid_from_world(x, y);
  EXPECT_EQ(dem.scene.valid[dem.scene.index(int(r), int(c))], 0);
  EXPECT_NEAR(double(dem.nodata_cells), double(expected_nodata(dem.scene, SourceDem(hgt))), 5.0);
}

TEST(DemImport, ReadSceneImportsAGeographicDemOnTheFly) {
  Scene s = read_scene(kDemDir + "SanAnd_dem.tif");
  ImportedDem dem = import_dem(kDemDir + "SanAnd_dem.tif");
  EXPECT_EQ(s.cols, dem.scene.cols);
  EXPECT_EQ(s.rows, dem.scene.rows);
  EXPECT_EQ(s.crs_wkt, dem.scene.crs_wkt);
  EXPECT_EQ(s.elevation_m, dem.scene.elevation_m);
  EXPECT_TRUE(dem_needs_import(kDemDir + "SanAnd_dem.tif"));
}

TEST(DemImport, UtmZoneAndRounding) {
  EXPECT_EQ(utm_zone_of_longitude(-180.0), 1);
  EXPECT_EQ(utm_zone_of_longitude(12.5), 33);
  EXPECT_EQ(utm_zone_of_longitude(-97.75), 14);
  EXPECT_EQ(utm_zone_of_longitude(179.99), 60);
  EXPECT_EQ(utm_zone_of_longitude(180.0), 1);
  EXPECT_DOUBLE_EQ(round_two_significant(26.93), 27.0);
  EXPECT_DOUBLE_EQ(round_two_significant(0.347), 0.35);
  EXPECT_DOUBLE_EQ(round_two_significant(92.6), 93.0);
  EXPECT_DOUBLE_EQ(round_two_significant(1234.0), 1200.0);
}

}  // namespace
}  // namespace ris
