// Products that overlay in a GIS (docs/outputs.md, "Geolocation of the
// slant-range products", "Geocoded greytones"): the default run's
// slant-range products carry GCPs that GDALWarp (gdalwarp) places onto the
// geocoded product; geocoded_grey.tif marks cells without a pixel by a mask
// band, so its black shadow cells stay valid; its PNG holds the same
// greytones; every product larger than one tile has overviews.
#include <gdal.h>
#include <gdal_utils.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

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

template <typename T>
std::vector<T> band(GDALDatasetH ds, GDALRasterBandH b, GDALDataType type) {
  const int cols = GDALGetRasterXSize(ds), rows = GDALGetRasterYSize(ds);
  std::vector<T> v(std::size_t(cols) * rows);
  EXPECT_EQ(GDALRasterIO(b, GF_Read, 0, 0, cols, rows, v.data(), cols, rows, type, 0, 0), CE_None);
  return v;
}

class OverlayCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new test::TempDir();
    const test::RunResult r =
        test::run_ris("simulate --quiet --threads 2 --out " + test::q(dir_->path() / "o"));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    GDALAllRegister();
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static fs::path out(const std::string& f) { return dir_->path() / "o" / f; }
  static test::TempDir* dir_;
};
test::TempDir* OverlayCli::dir_ = nullptr;

TEST_F(OverlayCli, SlantProductsCarryGcpsAndNoGeotransform) {
  for (const char* f : {"mean_power_slant.tif", "speckled_power_slant.tif", "mask_slant.tif"}) {
    Opened o(out(f));
    ASSERT_NE(o.ds, nullptr) << f;
    EXPECT_EQ(GDALGetGCPCount(o.ds), 400) << f;  // 20 x 20 tie points
    double gt[6];
    EXPECT_NE(GDALGetGeoTransform(o.ds, gt), CE_None) << f;
  }
}

TEST_F(OverlayCli, GdalwarpOfTheSlantPowerLandsOnTheGeocodedPower) {
  // Warped nearest with GDAL's thin-plate spline through the GCPs (-tps),
  // onto the geocoded product's grid: a cell takes the pixel geocoding gave
  // it unless the GCP fit moves it across a pixel edge. The fit is within
  // a cell of the exact geometry on smooth terrain
  // (SlantGeoref.GdalwarpWithTheGcpsLandsOnTheGeocodingWithinACell), so
  // most cells agree; the solids' walls and tops (layover, heights between
  // the tie points) are where a 2-D fit cannot follow. Measured: 89.7 % of
  // 696,500 cells take the very pixel geocoding gave them.
  Opened geo(out("geocoded_power.tif"));
  ASSERT_NE(geo.ds, nullptr);
  double gt[6];
  ASSERT_EQ(GDALGetGeoTransform(geo.ds, gt), CE_None);
  const int cols = GDALGetRasterXSize(geo.ds), rows = GDALGetRasterYSize(geo.ds);
  Opened src(out("speckled_power_slant.tif"));
  ASSERT_NE(src.ds, nullptr);
  std::vector<std::string> args = {"-of",
                                   "MEM",
                                   "-r",
                                   "near",
                                   "-tps",
                                   "-et",
                                   "0",
                                   "-te",
                                   std::to_string(gt[0]),
                                   std::to_string(gt[3] + rows * gt[5]),
                                   std::to_string(gt[0] + cols * gt[1]),
                                   std::to_string(gt[3]),
                                   "-ts",
                                   std::to_string(cols),
                                   std::to_string(rows)};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  GDALWarpAppOptions* opt = GDALWarpAppOptionsNew(argv.data(), nullptr);
  int usage_error = 0;
  GDALDatasetH src_ds = src.ds;
  GDALDatasetH warped = GDALWarp("", nullptr, 1, &src_ds, opt, &usage_error);
  GDALWarpAppOptionsFree(opt);
  ASSERT_NE(warped, nullptr);
  const auto w = band<float>(warped, GDALGetRasterBand(warped, 1), GDT_Float32);
  const auto g = band<float>(geo.ds, GDALGetRasterBand(geo.ds, 1), GDT_Float32);
  GDALClose(warped);
  std::size_t both = 0, same = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (!std::isfinite(g[i]) || !std::isfinite(w[i])) continue;
    ++both;
    if (w[i] == g[i]) ++same;
  }
  const double agree = double(same) / double(both);
  std::printf("cells compared %zu, same pixel %.4f\n", both, agree);
  EXPECT_GT(both, g.size() / 2);
  EXPECT_GT(agree, 0.85);
}

TEST_F(OverlayCli, GeocodedGreyMasksCellsWithoutAPixelAndKeepsBlackShadowValid) {
  Opened grey(out("geocoded_grey.tif"));
  Opened power(out("geocoded_power.tif"));
  Opened mask(out("scene_mask.tif"));
  ASSERT_NE(grey.ds, nullptr);
  GDALRasterBandH b = GDALGetRasterBand(grey.ds, 1);
  int has_nodata = 0;
  GDALGetRasterNoDataValue(b, &has_nodata);
  EXPECT_EQ(has_nodata, 0);  // no value can be spared: 0 is black
  EXPECT_EQ(GDALGetMaskFlags(b), GMF_PER_DATASET);
  const auto v = band<std::uint8_t>(grey.ds, b, GDT_Byte);
  const auto m = band<std::uint8_t>(grey.ds, GDALGetMaskBand(b), GDT_Byte);
  const auto p = band<float>(power.ds, GDALGetRasterBand(power.ds, 1), GDT_Float32);
  const auto sm = band<std::uint8_t>(mask.ds, GDALGetRasterBand(mask.ds, 1), GDT_Byte);
  std::size_t black_shadow_valid = 0, shadow = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    ASSERT_EQ(m[i], std::isnan(p[i]) ? 0 : 255) << i;  // the power's cells with data
    if ((sm[i] & 1) && !std::isnan(p[i])) {
      ++shadow;
      if (v[i] == 0) ++black_shadow_valid;
    }
  }
  // Most shadow cells are black (0) and every one of them is valid.
  EXPECT_GT(black_shadow_valid, shadow / 2);
}

TEST_F(OverlayCli, GeocodedPngHoldsTheGeocodedGreytones) {
  Opened tif(out("geocoded_grey.tif"));
  Opened png(out("geocoded_grey.png"));
  ASSERT_NE(png.ds, nullptr);
  EXPECT_EQ(GDALGetRasterXSize(png.ds), GDALGetRasterXSize(tif.ds));
  EXPECT_EQ(GDALGetRasterYSize(png.ds), GDALGetRasterYSize(tif.ds));
  EXPECT_EQ(band<std::uint8_t>(png.ds, GDALGetRasterBand(png.ds, 1), GDT_Byte),
            band<std::uint8_t>(tif.ds, GDALGetRasterBand(tif.ds, 1), GDT_Byte));
}

TEST_F(OverlayCli, ProductsAboveOneTileHaveOverviews) {
  // 1000 x 700 (scene grid): 500, 250; 241 x 700 (slant): 350, 175.
  for (const char* f : {"geocoded_power.tif", "geocoded_grey.tif", "scene_mask.tif",
                        "local_incidence_deg.tif", "mean_power_slant.tif", "mask_slant.tif"}) {
    Opened o(out(f));
    ASSERT_NE(o.ds, nullptr) << f;
    EXPECT_EQ(GDALGetOverviewCount(GDALGetRasterBand(o.ds, 1)), 2) << f;
  }
}

}  // namespace
}  // namespace ris
