#include "ris/io/geotiff_block_writer.h"

#include <gdal.h>
#include <gtest/gtest.h>

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

TEST(GeoTiffBlockWriter, LargeRastersGetOverviewsUnlessTurnedOff) {
  test::TempDir dir;
  const int n = 4096;  // kOverviewMinPixels
  const std::vector<std::uint8_t> zeros(std::size_t(n) * 64, 0);
  for (const bool on : {true, false}) {
    GeoTiffCompression c;
    c.overviews = on;
    const auto path = dir / (on ? "on.tif" : "off.tif");
    GeoTiffBlockWriter<std::uint8_t> w(path, n, n, {"mask"}, nullptr, std::nullopt, {}, c);
    for (int r = 0; r < n; r += 64) w.write(zeros.data(), 64);
    w.close();
    GDALAllRegister();
    GDALDatasetH ds = GDALOpen(path.c_str(), GA_ReadOnly);
    ASSERT_NE(ds, nullptr);
    // 2, 4, ..., 16: the last keeps 256 pixels a side.
    EXPECT_EQ(GDALGetOverviewCount(GDALGetRasterBand(ds, 1)), on ? 4 : 0);
    GDALClose(ds);
  }
}

}  // namespace
}  // namespace ris
