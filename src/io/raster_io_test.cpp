// encode_png: the in-memory PNG the server sends holds the pixels given, for
// grey, RGB and RGBA.
#include "ris/io/raster_io.h"

#include <gtest/gtest.h>

#include <vector>

#include "test_util.h"

namespace ris {
namespace {

// The pixels of a PNG in memory, read back through GDAL.
RasterF64 decode(const std::vector<std::uint8_t>& png, const test::TempDir& tmp) {
  test::write_file(tmp / "decoded.png", std::string(png.begin(), png.end()));
  return read_raster_f64(tmp / "decoded.png");
}

TEST(EncodePng, GreyRgbAndRgbaPixelsComeBack) {
  test::TempDir tmp;
  const int cols = 7;
  const int rows = 5;
  for (const int channels : {1, 3, 4}) {
    std::vector<std::uint8_t> pixels(static_cast<std::size_t>(cols * rows * channels));
    for (std::size_t i = 0; i < pixels.size(); ++i) {
      pixels[i] = static_cast<std::uint8_t>(37 * i + 5);
    }
    const RasterF64 back = decode(encode_png(pixels.data(), cols, rows, channels), tmp);
    ASSERT_EQ(back.bands, channels);
    ASSERT_EQ(back.cols, cols);
    ASSERT_EQ(back.rows, rows);
    // Bands are stored one after the other; the input is interleaved.
    for (int b = 0; b < channels; ++b) {
      for (int i = 0; i < cols * rows; ++i) {
        ASSERT_EQ(back.data[static_cast<std::size_t>(b * cols * rows + i)],
                  pixels[static_cast<std::size_t>(channels * i + b)])
            << "channels " << channels << ", band " << b << ", pixel " << i;
      }
    }
  }
}

}  // namespace
}  // namespace ris
