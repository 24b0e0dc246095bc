// The azimuth step of SLAR image formation (ris/image/slar_image.h) as a
// stream: per-line range profiles go in, in line order, a block at a time;
// image lines come out as soon as every line their footprint covers is in.
// integrate_slar_azimuth (the whole image at once) is built on it, so a
// streamed image (ris/sim/slar_stream.h) is the same bytes.
//
// The pixel on line k integrates the piecewise-constant profile over
// [k - half, k + half] (line units; line j stands for [j - 1/2, j + 1/2];
// half = w(R) / (2 ds), w = R phi at the bin centre for SLAR, or the constant
// window of SAR/PPI) by differences of running sums over lines per bin,
// cum[j] = profile of lines 0..j-1 summed in line order. Only the running
// sums within M = ceil(max half) + 2 lines of the next line to emit are
// kept, so memory is (block + 2 M) lines x bins, whatever the image length.
//
// An integrator may also hold only the bins [bin_begin, bin_end) of the
// image (every pixel depends on its own bin's column alone): then push()
// and emit() run on the calling thread, so that threads each take a range
// of bins through the whole image in one parallel region, with no barrier
// between blocks of lines (integrate_slar_azimuth does this; the whole-image
// integrator splits each push and emit over the threads instead, which is
// two barriers per block).
//
// Example:
//   ris::SlarAzimuthIntegrator az(params, line_spacing_m, lines, bins);
//   az.push(profiles_block, profiles_block.lines);  // lines [az.lines_pushed(), ...)
//   const int n = az.lines_ready();
//   az.emit(n, power.data(), area.data(), mask.data());  // n x bins each
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "ris/image/slar_image.h"
#include "ris/util/default_init_allocator.h"

namespace ris {

class SlarAzimuthIntegrator {
 public:
  // lines, bins: the whole image's size. [bin_begin, bin_end): the bins this
  // integrator holds (bin_end < 0: to the last); with a part of the bins it
  // runs single-threaded (see above).
  SlarAzimuthIntegrator(const SlarImagingParams& params, double line_spacing_m, int lines, int bins,
                        int bin_begin = 0, int bin_end = -1);

  // Adds the profiles of the next `count` lines, [lines_pushed(),
  // lines_pushed() + count), which `prof` must hold (prof.bins: the image's).
  void push(const SlarLineProfiles& prof, int count);

  int lines_pushed() const { return pushed_; }
  int lines_emitted() const { return emitted_; }
  // How many more lines emit() can produce now (all that are left once every
  // line has been pushed).
  int lines_ready() const;
  // The next `count` (<= lines_ready()) image lines of the bins held: count
  // rows of mean power (W), area (m^2) and pixel_flag mask, each pointer at
  // the first row's first bin held, rows `row_stride` apart (0: the number of
  // bins held).
  void emit(int count, float* mean_power_w, float* area_m2, std::uint8_t* mask,
            std::size_t row_stride = 0);

 private:
  std::size_t row(int cum_index) const;  // offset of a running-sum row
  // The bins [lo, hi) of those held that line k's footprint may see data
  // in: the union of the data extents of the lines within M of k.
  std::pair<int, int> active_bins(int k) const;

  int lines_ = 0;
  int bin0_ = 0, bins_ = 0;   // the bins held: [bin0_, bin0_ + bins_)
  bool threaded_ = true;      // push and emit split over the threads
  int margin_ = 0;            // M
  std::vector<double> half_;  // per bin, lines
  int pushed_ = 0, emitted_ = 0;
  int base_ = 0;  // running-sum index of the first kept row
  // Grown a block of lines at a time and written in full by push(): no zero
  // fill (ris/util/default_init_allocator.h).
  template <typename T>
  using Rows = std::vector<T, DefaultInitAllocator<T>>;
  Rows<double> cum_, cum_area_;
  Rows<int> cum_data_, cum_visible_, cum_layover_;
  // Per line pushed, the bins [lo, hi) (of those held) outside which its
  // profile is zero (power, area and touch bits): beyond the union of these
  // over a footprint, emit() writes the no-data pixel without reading the
  // running sums (about half of an oblique track's image).
  std::vector<std::pair<int, int>> extent_;
  std::vector<std::pair<int, int>> part_extent_;  // push(): per thread and line
};

}  // namespace ris
