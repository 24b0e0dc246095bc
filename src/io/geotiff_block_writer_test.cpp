#include "ris/io/geotiff_block_writer.h"

#include <gdal.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "test_util.h"

namespace ris {
namespace {

// A raster bigger than one tile each way, with edge tiles that are partial.
constexpr int kCols = 300, kRows = 520;

std::vector<float> pattern() {
  std::vector<float> v(static_cast<std::size_t>(kCols) * kRows);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = static_cast<float>((i * 7919) % 1000) * 0.5f;
  return v;
}

// Writes `data` in blocks of `block` rows or columns in `order`.
void write_blocks(const std::filesystem::path& path, const std::vector<float>& data,
                  BlockOrder order, int block) {
  const Georef g{{100.0, 2.0, 0.0, 500.0, 0.0, -2.0}, ""};
  GeoTiffBlockWriter<float> w(path, kCols, kRows, {"v"}, &g, -1.0, {{"K", "V"}}, {}, order);
  const bool rows = order == BlockOrder::top_down || order == BlockOrder::bottom_up;
  const bool up = order == BlockOrder::top_down || order == BlockOrder::left_right;
  const int n = rows ? kRows : kCols;
  for (int done = 0; done < n; done += block) {
    const int count = std::min(block, n - done);
    const int lo = up ? done : n - done - count;
    if (rows) {
      w.write(data.data() + static_cast<std::size_t>(lo) * kCols, count);
    } else {
      w.write(data.data() + lo, count, kCols);
    }
  }
  w.close();
}

TEST(GeoTiffBlockWriter, AnyBlockSizeGivesTheSameFileAndPixels) {
  const std::vector<float> data = pattern();
  test::TempDir dir;
  for (BlockOrder order : {BlockOrder::top_down, BlockOrder::bottom_up, BlockOrder::left_right,
                           BlockOrder::right_left}) {
    const auto whole = dir / "whole.tif";
    write_blocks(whole, data, order, 100000);
    const RasterF64 r = read_raster_f64(whole);
    ASSERT_EQ(r.cols, kCols);
    ASSERT_EQ(r.rows, kRows);
    for (std::size_t i = 0; i < data.size(); ++i) ASSERT_EQ(r.data[i], double(data[i])) << i;
    EXPECT_EQ(r.nodata, -1.0);
    EXPECT_EQ(r.metadata.at("K"), "V");
    EXPECT_EQ(r.georef.geotransform[0], 100.0);
    const std::string bytes = test::read_file(whole);
    for (int block : {1, 7, 256, 300}) {
      const auto part = dir / "part.tif";
      write_blocks(part, data, order, block);
      EXPECT_TRUE(test::read_file(part) == bytes) << int(order) << " block " << block;
    }
  }
  // write_geotiff is the same writer.
  write_geotiff<float>(dir / "api.tif", data.data(), kCols, kRows, nullptr);
  write_blocks(dir / "b.tif", data, BlockOrder::top_down, 33);
  EXPECT_EQ(read_raster_f64(dir / "api.tif").data, read_raster_f64(dir / "b.tif").data);
}

TEST(GeoTiffBlockWriter, NothingIsLeftWithoutClose) {
  test::TempDir dir;
  {
    GeoTiffBlockWriter<std::uint8_t> w(dir / "x.tif", 10, 10, {""}, nullptr);
    std::vector<std::uint8_t> row(10, 1);
    w.write(row.data(), 1);
  }
  EXPECT_TRUE(std::filesystem::is_empty(dir.path()));
}

TEST(GeoTiffBlockWriter, EveryBandDeclaresItsUnit) {
  EXPECT_EQ(band_unit("speckled_power_w", {{"RIS_UNITS", "W"}}, 1), "W");
  EXPECT_EQ(band_unit("elevation_m", {}, 2), "m");
  EXPECT_EQ(band_unit("category", {}, 2), "");
  EXPECT_EQ(band_unit("mask", {}, 1), "bits");
  EXPECT_EQ(band_unit("latitude_deg (WGS 84)", {}, 1), "deg");
  EXPECT_EQ(band_unit("greytone", {}, 1), "greytone");
  test::TempDir dir;
  GeoTiffBlockWriter<float> w(dir / "u.tif", 4, 3, {"elevation_m", "category"}, nullptr);
  const std::vector<float> z(12, 1.0f);
  w.write({z.data(), z.data()}, 3);
  w.close();
  GDALAllRegister();
  GDALDatasetH ds = GDALOpen((dir / "u.tif").c_str(), GA_ReadOnly);
  ASSERT_NE(ds, nullptr);
  EXPECT_STREQ(GDALGetRasterUnitType(GDALGetRasterBand(ds, 1)), "m");
  EXPECT_STREQ(GDALGetRasterUnitType(GDALGetRasterBand(ds, 2)), "");
  GDALClose(ds);
}

// The overviews a raster of cols x rows gets (0 when it cannot be opened).
int overview_count(const std::filesystem::path& path, int cols, int rows, bool on) {
  const std::vector<std::uint8_t> zeros(std::size_t(cols) * rows, 0);
  GeoTiffCompression c;
  c.overviews = on;
  GeoTiffBlockWriter<std::uint8_t> w(path, cols, rows, {"mask"}, nullptr, std::nullopt, {}, c);
  w.write(zeros.data(), rows);
  w.close();
  GDALAllRegister();
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  if (ds == nullptr) return 0;
  const int n = GDALGetOverviewCount(GDALGetRasterBand(ds, 1));
  GDALClose(ds);
  return n;
}

TEST(GeoTiffBlockWriter, RastersAboveOneTileGetOverviewsUnlessTurnedOff) {
  test::TempDir dir;
  // Halvings until the overview fits in one 256-pixel tile (gdaladdo's
  // default): 4096 -> 2, 4, 8, 16; 300 x 100 -> 2; 257 -> 2; one tile -> none.
  EXPECT_EQ(overview_count(dir / "big.tif", 4096, 4096, true), 4);
  EXPECT_EQ(overview_count(dir / "off.tif", 4096, 4096, false), 0);
  EXPECT_EQ(overview_count(dir / "small.tif", 300, 100, true), 1);
  EXPECT_EQ(overview_count(dir / "tall.tif", 20, 257, true), 1);
  EXPECT_EQ(overview_count(dir / "odd.tif", 1000, 700, true), 2);  // 500, 250
  EXPECT_EQ(overview_count(dir / "tile.tif", 256, 256, true), 0);
}

TEST(GeoTiffBlockWriter, MaskBandMarksCellsWithoutDataWhateverTheirValue) {
  // A greytone of 0 is valid: the mask, not a no-data value, says which
  // pixels hold data, and 0-valued pixels with data stay valid.
  test::TempDir dir;
  const int cols = 300, rows = 40;
  std::vector<std::uint8_t> grey(std::size_t(cols) * rows, 0), valid(grey.size(), 1);
  for (int c = 0; c < cols; ++c) valid[std::size_t(7) * cols + std::size_t(c)] = 0;  // row 7
  grey[5] = 200;
  const auto path = dir / "masked.tif";
  GeoTiffBlockWriter<std::uint8_t> w(path, cols, rows, {"greytone"}, nullptr);
  w.add_mask_band();
  for (int r = 0; r < rows; r += 16) {
    const int n = std::min(16, rows - r);
    w.write(grey.data() + std::size_t(r) * cols, n, 0, valid.data() + std::size_t(r) * cols);
  }
  w.close();
  EXPECT_FALSE(std::filesystem::exists(dir / "masked.tif.msk"));  // internal
  GDALAllRegister();
  GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
  ASSERT_NE(ds, nullptr);
  GDALRasterBandH band = GDALGetRasterBand(ds, 1);
  int has_nodata = 0;
  GDALGetRasterNoDataValue(band, &has_nodata);
  EXPECT_EQ(has_nodata, 0);
  EXPECT_EQ(GDALGetMaskFlags(band), GMF_PER_DATASET);
  std::vector<std::uint8_t> m(grey.size());
  ASSERT_EQ(GDALRasterIO(GDALGetMaskBand(band), GF_Read, 0, 0, cols, rows, m.data(), cols, rows,
                         GDT_Byte, 0, 0),
            CE_None);
  for (std::size_t i = 0; i < m.size(); ++i) ASSERT_EQ(m[i], valid[i] ? 255 : 0) << i;
  GDALClose(ds);
}

}  // namespace
}  // namespace ris
