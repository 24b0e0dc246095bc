// The page's difference view of two runs on the same grid
// (ris/serve/run_history.h): per slant pixel d = 10 log10(current / earlier)
// of the mean power (speckle-free: what the radar change did) or of the
// speckled power (what the two pictures show), on a diverging colour ramp
// centred on 0 dB with its colour key.
//
// The ramp is ColorBrewer's 11-class RdBu (Brewer, Harrower and The
// Pennsylvania State University, colorbrewer2.org; Harrower and Brewer 2003,
// "ColorBrewer.org: an online tool for selecting colour schemes for maps",
// The Cartographic Journal 40(1)), reversed so that blue is darker now and
// red brighter now, interpolated linearly between its classes across
// [-range_db, +range_db] and clamped beyond. Pixels without a finite d (no
// data, or zero power in either run) are transparent.
//
// Example:
//   const ris::Difference d = ris::difference_db(cur, earlier, ris::CompareQuantity::mean);
//   std::vector<std::uint8_t> png = ris::difference_png(d, 6.0);
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/serve/run_history.h"

namespace ris {

enum class CompareQuantity { mean, speckled };

// "mean" or "speckled"; InputError (source "request", key "quantity") else.
CompareQuantity parse_compare_quantity(const std::string& text);
std::string compare_quantity_name(CompareQuantity q);

struct Difference {
  int lines = 0;
  int bins = 0;
  std::vector<float> db;  // lines x bins; NaN: no finite difference
};

// Both runs on the same grid (check_same_grid first).
Difference difference_db(const KeptRun& current, const KeptRun& earlier, CompareQuantity q);

// The difference in dB of one pixel: 10 log10(current / earlier); NaN when
// either is not positive.
double pixel_difference_db(double current_w, double earlier_w);

// The symmetric range the view spans by default: the 98th percentile of |d|
// rounded up to a whole dB, at least 1 dB.
double default_range_db(const Difference& d);

// The ramp's colour for d (dB) over [-range_db, range_db].
std::array<std::uint8_t, 3> difference_colour(double d_db, double range_db);

// The colour key: the ramp's 11 classes at their dB values.
nlohmann::json difference_key(double range_db);

// RGBA PNG, bins across, lines down (the slant view's layout).
std::vector<std::uint8_t> difference_png(const Difference& d, double range_db);

}  // namespace ris
