// encode_png: the in-memory PNG the server sends is the file the writers
// write, for grey, RGB and RGBA pixels.
#include "ris/io/raster_io.h"

#include <gtest/gtest.h>

#include <vector>

#include "test_util.h"

namespace ris {
namespace {

TEST(EncodePng, SameBytesAsTheFileWriter) {
  test::TempDir tmp;
  const int cols = 7;
  const int rows = 5;
  std::vector<std::uint8_t> grey(cols * rows);
  std::vector<std::uint8_t> rgb(cols * rows * 3);
  for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = static_cast<std::uint8_t>(37 * i);
  for (std::size_t i = 0; i < rgb.size(); ++i) rgb[i] = static_cast<std::uint8_t>(11 * i + 3);
  write_png_gray(tmp / "g.png", grey.data(), cols, rows);
  write_png_rgb(tmp / "c.png", rgb.data(), cols, rows);
  const std::vector<std::uint8_t> g = encode_png(grey.data(), cols, rows, 1);
  const std::vector<std::uint8_t> c = encode_png(rgb.data(), cols, rows, 3);
  EXPECT_EQ(std::string(g.begin(), g.end()), test::read_file(tmp / "g.png"));
  EXPECT_EQ(std::string(c.begin(), c.end()), test::read_file(tmp / "c.png"));
  // RGBA: the pixels come back as written.
  std::vector<std::uint8_t> rgba(cols * rows * 4);
  for (std::size_t i = 0; i < rgba.size(); ++i) rgba[i] = static_cast<std::uint8_t>(5 * i);
  const std::vector<std::uint8_t> a = encode_png(rgba.data(), cols, rows, 4);
  test::write_file(tmp / "a.png", std::string(a.begin(), a.end()));
  const RasterF64 back = read_raster_f64(tmp / "a.png");
  ASSERT_EQ(back.bands, 4);
  ASSERT_EQ(back.cols, cols);
  for (int b = 0; b < 4; ++b) {
    for (int i = 0; i < cols * rows; ++i) {
      EXPECT_EQ(back.data[static_cast<std::size_t>(b * cols * rows + i)], rgba[4 * i + b]);
    }
  }
}

}  // namespace
}  // namespace ris
