// Acquisition-grid products that overlay in a GIS (docs/outputs.md,
// "Geolocation of the acquisition-grid products"): `ris simulate
// --acquisition` writes its rasters with GCPs in latitude/longitude
// (EPSG:4326, as Sentinel-1's measurement GeoTIFFs), and gdalwarp through
// them puts each pixel where `ris topo`'s latitude/longitude layers say it
// is, within a pixel.
#include <gdal.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "acquisition_paths.h"
#include "ris/io/raster_io.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

struct Opened {
  explicit Opened(const fs::path& p) : ds(GDALOpen(p.c_str(), GA_ReadOnly)) {}
  ~Opened() {
    if (ds != nullptr) GDALClose(ds);
  }
  GDALDatasetH ds;
};

class OverlayAcquisitionCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir();
    const std::string inputs =
        " -a " + test::winnipeg_h5() + " --dem " + test::test_dem("winnipeg_dem.tif");
    const auto sim = test::run_ris("simulate --quiet --threads 2" + inputs + " --out " +
                                   test::q(dir_->path() / "o"));
    ASSERT_EQ(sim.exit_code, 0) << sim.output;
    const auto topo =
        test::run_ris("topo --threads 2" + inputs + " --out " + test::q(dir_->path() / "t"));
    ASSERT_EQ(topo.exit_code, 0) << topo.output;
    GDALAllRegister();
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static fs::path out(const std::string& f) { return dir_->path() / "o" / f; }
  static fs::path topo(const std::string& f) { return dir_->path() / "t" / f; }
  static test::TempDir* dir_;
};
test::TempDir* OverlayAcquisitionCli::dir_ = nullptr;

TEST_F(OverlayAcquisitionCli, WindowProductsCarryLatLonGcpsAndNoGeotransform) {
  for (const char* f : {"mean_power_slant.tif", "speckled_power_slant.tif", "mask_slant.tif",
                        "local_incidence.tif", "layover_shadow_mask.tif"}) {
    Opened o(out(f));
    ASSERT_NE(o.ds, nullptr) << f;
    EXPECT_EQ(GDALGetGCPCount(o.ds), 1024) << f;  // 32 x 32 tie points
    EXPECT_NE(std::string(GDALGetGCPProjection(o.ds)).find("4326"), std::string::npos) << f;
    double gt[6];
    EXPECT_NE(GDALGetGeoTransform(o.ds, gt), CE_None) << f;
  }
  // The GCPs' ground is the topo layers' at the same pixel centres (rdr2geo
  // of the same time and range on the same DEM).
  Opened o(out("mean_power_slant.tif"));
  const RasterF64 lat = read_raster_f64(topo("lat.tif"));
  const RasterF64 lon = read_raster_f64(topo("lon.tif"));
  const RasterF64 power = read_raster_f64(out("mean_power_slant.tif"));
  const int dl = std::stoi(power.metadata.at("RIS_WINDOW_FIRST_LINE")) -
                 std::stoi(lat.metadata.at("RIS_WINDOW_FIRST_LINE"));
  const int db = std::stoi(power.metadata.at("RIS_WINDOW_FIRST_BIN")) -
                 std::stoi(lat.metadata.at("RIS_WINDOW_FIRST_BIN"));
  const GDAL_GCP* gcps = GDALGetGCPs(o.ds);
  double worst_deg = 0.0;
  for (int i = 0; i < GDALGetGCPCount(o.ds); ++i) {
    // At pixel centres: bin k's value is range sample k's.
    EXPECT_EQ(gcps[i].dfGCPPixel - std::floor(gcps[i].dfGCPPixel), 0.5) << i;
    EXPECT_EQ(gcps[i].dfGCPLine - std::floor(gcps[i].dfGCPLine), 0.5) << i;
    const int k = static_cast<int>(gcps[i].dfGCPPixel) + db;
    const int l = static_cast<int>(gcps[i].dfGCPLine) + dl;
    ASSERT_TRUE(k >= 0 && k < lat.cols && l >= 0 && l < lat.rows) << i;
    const std::size_t at = std::size_t(l) * lat.cols + k;
    worst_deg = std::max({worst_deg, std::abs(gcps[i].dfGCPY - lat.data[at]),
                          std::abs(gcps[i].dfGCPX - lon.data[at])});
  }
  EXPECT_LT(worst_deg, 1e-9);  // about 0.1 mm
}

// The distance in metres between two nearby points (local flat Earth).
double metres(double lat1, double lon1, double lat2, double lon2) {
  constexpr double kMetresPerDeg = 111320.0;
  const double c = std::cos(lat1 * 3.14159265358979323846 / 180.0);
  return kMetresPerDeg * std::hypot(lat2 - lat1, (lon2 - lon1) * c);
}

TEST_F(OverlayAcquisitionCli, GdalwarpThroughTheGcpsLandsWhereTopoSaysWithinAPixel) {
  // A copy of the product's grid whose two bands are each pixel's bin and
  // line, with the product's GCPs, warped to latitude/longitude as a GIS
  // would (nearest, thin-plate spline through the GCPs): each warped cell
  // names the pixel it took, and topo says where that pixel's ground is.
  Opened o(out("mean_power_slant.tif"));
  ASSERT_NE(o.ds, nullptr);
  const int cols = GDALGetRasterXSize(o.ds), rows = GDALGetRasterYSize(o.ds);
  GDALDatasetH index =
      GDALCreate(GDALGetDriverByName("MEM"), "", cols, rows, 2, GDT_Float64, nullptr);
  std::vector<double> bin(std::size_t(cols) * rows), line(bin.size());
  for (int l = 0; l < rows; ++l) {
    for (int k = 0; k < cols; ++k) {
      bin[std::size_t(l) * cols + k] = k;
      line[std::size_t(l) * cols + k] = l;
    }
  }
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(index, 1), GF_Write, 0, 0, cols, rows, bin.data(), cols,
                         rows, GDT_Float64, 0, 0),
            CE_None);
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(index, 2), GF_Write, 0, 0, cols, rows, line.data(), cols,
                         rows, GDT_Float64, 0, 0),
            CE_None);
  GDALSetGCPs(index, GDALGetGCPCount(o.ds), GDALGetGCPs(o.ds), GDALGetGCPProjection(o.ds));
  std::vector<std::string> args = {"-of", "MEM", "-r",         "near", "-tps",
                                   "-et", "0",   "-dstnodata", "-1"};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALWarpAppOptions* opt = GDALWarpAppOptionsNew(argv.data(), nullptr);
  int usage_error = 0;
  GDALDatasetH warped = GDALWarp("", nullptr, 1, &index, opt, &usage_error);
  GDALWarpAppOptionsFree(opt);
  ASSERT_NE(warped, nullptr);
  const int wc = GDALGetRasterXSize(warped), wr = GDALGetRasterYSize(warped);
  double gt[6];
  ASSERT_EQ(GDALGetGeoTransform(warped, gt), CE_None);
  std::vector<double> wk(std::size_t(wc) * wr), wl(wk.size());
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(warped, 1), GF_Read, 0, 0, wc, wr, wk.data(), wc, wr,
                         GDT_Float64, 0, 0),
            CE_None);
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(warped, 2), GF_Read, 0, 0, wc, wr, wl.data(), wc, wr,
                         GDT_Float64, 0, 0),
            CE_None);
  GDALClose(warped);
  GDALClose(index);

  const RasterF64 lat = read_raster_f64(topo("lat.tif"));
  const RasterF64 lon = read_raster_f64(topo("lon.tif"));
  const RasterF64 power = read_raster_f64(out("mean_power_slant.tif"));
  const int dl = std::stoi(power.metadata.at("RIS_WINDOW_FIRST_LINE")) -
                 std::stoi(lat.metadata.at("RIS_WINDOW_FIRST_LINE"));
  const int db = std::stoi(power.metadata.at("RIS_WINDOW_FIRST_BIN")) -
                 std::stoi(lat.metadata.at("RIS_WINDOW_FIRST_BIN"));
  const auto topo_at = [&](int l, int k) {
    const std::size_t at = std::size_t(l + dl) * lat.cols + (k + db);
    return std::pair{lat.data[at], lon.data[at]};
  };
  // A pixel's size on the ground: to its neighbours in range and azimuth.
  std::size_t cells = 0;
  double worst = 0.0, sum = 0.0;
  for (int r = 0; r < wr; ++r) {
    for (int c = 0; c < wc; ++c) {
      const std::size_t i = std::size_t(r) * wc + c;
      if (wk[i] < 0.0) continue;
      const int k = static_cast<int>(wk[i]), l = static_cast<int>(wl[i]);
      if (k + 1 >= cols || l + 1 >= rows) continue;
      const auto [la, lo] = topo_at(l, k);
      const auto [la_r, lo_r] = topo_at(l, k + 1);
      const auto [la_a, lo_a] = topo_at(l + 1, k);
      const double pixel_m =
          std::hypot(metres(la, lo, la_r, lo_r), metres(la, lo, la_a, lo_a));  // its diagonal
      const double cell_lon = gt[0] + (c + 0.5) * gt[1];
      const double cell_lat = gt[3] + (r + 0.5) * gt[5];
      const double err = metres(la, lo, cell_lat, cell_lon) / pixel_m;
      worst = std::max(worst, err);
      sum += err;
      ++cells;
    }
  }
  std::printf(
      "warped cells %zu (of %d x %d), distance to topo's ground / pixel diagonal: mean "
      "%.3f, worst %.3f\n",
      cells, wc, wr, sum / double(cells), worst);
  EXPECT_GT(cells, std::size_t(cols) * rows / 2);
  // Nearest: a cell's centre lies in the pixel it took (within 0.71 of the
  // diagonal of its centre), plus what the spline between the tie points
  // misses. Measured: mean 0.27, worst 0.96 with 32 x 32 points (20 x 20
  // gave 1.04 on this airborne product).
  EXPECT_LT(worst, 1.0);
  EXPECT_LT(sum / double(cells), 0.35);
}

}  // namespace
}  // namespace ris
