// The ground-range presentation: each azimuth line resampled from slant range
// to uniform ground range over a reference height h_ref (flat earth, as on
// the seed's IDECS display; MODEL.md section 3, "Presentations"):
//   u = sqrt(R^2 - (H - h_ref)^2).
// Pixel j covers ground range [u_near + j du, u_near + (j + 1) du] and takes
// the slant-range raster linearly interpolated between bin centres at the
// slant range of its centre (masks: the nearest bin). Columns are near range
// first, rows are the slant-range image's rows.
//
// Example:
//   ris::GroundRangeGrid grid = ris::ground_range_grid(img.range, H, 0.0, img.line_spacing_m);
//   std::vector<float> ground = ris::to_ground_range(img.mean_power_w, img.lines, img.range, grid);
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "ris/image/slar_image.h"

namespace ris {

struct GroundRangeGrid {
  double altitude_m = 0.0;          // H above the datum
  double reference_height_m = 0.0;  // h_ref
  double near_m = 0.0;              // ground range of the first pixel's near edge
  double spacing_m = 0.0;           // du
  int count = 0;
  double centre_m(int j) const { return near_m + (j + 0.5) * spacing_m; }
};

// The grid covering the slant-range swath [near, far] at spacing_m. Throws
// InputError (key "reference_height") when h_ref is at or above the sensor.
GroundRangeGrid ground_range_grid(const SlantRangeBins& bins, double altitude_m,
                                  double reference_height_m, double spacing_m);

// The resampling of one azimuth line, set up once per grid: each ground
// pixel's two bins and weight (linear) and its nearest bin. The kernel of
// to_ground_range, to_ground_range_nearest and the fused render
// (ris/sim/slar_simulation.h).
class GroundRangeResampler {
 public:
  GroundRangeResampler(const SlantRangeBins& bins, const GroundRangeGrid& grid);
  int columns() const { return static_cast<int>(weight_.size()); }
  // slant: one line of bins.count floats; out: columns() floats (NaN beyond
  // the swath; NaN bins stay NaN).
  void resample_line(const float* slant, float* out) const;
  // A run of columns [begin, end).
  struct Columns {
    std::size_t begin = 0, end = 0;
  };
  // The columns whose two bins both lie in [first_bin, end_bin): one run,
  // since the bins grow with the column. When a line's bins outside that
  // range are NaN, these are the only columns resample_line can give a
  // number (a + f (b - a) is NaN when a or b is).
  Columns columns_within(int first_bin, int end_bin) const;
  // resample_line with the columns outside `cols` (a run columns_within
  // gave) set to NaN without reading the line: the same bytes as
  // resample_line when the line's bins outside the range are NaN. Used by the
  // render to skip an oblique track's no-data ends.
  void resample_line(const float* slant, float* out, Columns cols) const;
  // The same for bytes, nearest bin; `fill` beyond the swath.
  void nearest_line(const std::uint8_t* slant, std::uint8_t* out, std::uint8_t fill) const;

 private:
  // Per ground pixel: the bins k0 and k1 (0 beyond the swath) and weight f,
  // out = a + f (b - a) in double; inside_ 0 beyond the swath. nearest_: the
  // nearest bin, -1 beyond the swath.
  std::vector<std::int32_t> k0_, k1_, nearest_;
  std::vector<double> weight_;
  std::vector<std::uint8_t> inside_;
  // The runs of columns inside the swath and with a nearest bin.
  std::size_t inside_begin_ = 0, inside_end_ = 0, nearest_begin_ = 0, nearest_end_ = 0;
  int bins_ = 0;  // a line's bins (the vector kernels' loads stay inside it)
};

// Resamples a lines x bins float raster (power) to lines x grid.count; NaN
// bins stay NaN, pixels beyond the swath are NaN.
std::vector<float> to_ground_range(std::span<const float> slant, int lines,
                                   const SlantRangeBins& bins, const GroundRangeGrid& grid);

// The same for a byte raster (mask), nearest bin; fill beyond the swath.
std::vector<std::uint8_t> to_ground_range_nearest(std::span<const std::uint8_t> slant, int lines,
                                                  const SlantRangeBins& bins,
                                                  const GroundRangeGrid& grid, std::uint8_t fill);

}  // namespace ris
