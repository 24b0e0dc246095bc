#include "ris/serve/run_compare.h"

#include <algorithm>
#include <cmath>

#include "ris/io/raster_io.h"
#include "ris/util/error.h"

namespace ris {
namespace {

// ColorBrewer RdBu, 11 classes, reversed: dark blue (most negative) to dark
// red (most positive), the middle class (index 5) at 0 dB.
constexpr std::array<std::array<int, 3>, 11> kRamp = {{{5, 48, 97},
                                                       {33, 102, 172},
                                                       {67, 147, 195},
                                                       {146, 197, 222},
                                                       {209, 229, 240},
                                                       {247, 247, 247},
                                                       {253, 219, 199},
                                                       {244, 165, 130},
                                                       {214, 96, 77},
                                                       {178, 24, 43},
                                                       {103, 0, 31}}};

}  // namespace

CompareQuantity parse_compare_quantity(const std::string& text) {
  if (text.empty() || text == "mean") return CompareQuantity::mean;
  if (text == "speckled") return CompareQuantity::speckled;
  throw InputError(
      "request", "quantity",
      "expected \"mean\" (mean power) or \"speckled\" (speckled power), got \"" + text + "\"");
}

std::string compare_quantity_name(CompareQuantity q) {
  return q == CompareQuantity::mean ? "mean" : "speckled";
}

double pixel_difference_db(double current_w, double earlier_w) {
  if (!(current_w > 0.0) || !(earlier_w > 0.0)) return NAN;
  return 10.0 * std::log10(current_w / earlier_w);
}

Difference difference_db(const KeptRun& current, const KeptRun& earlier, CompareQuantity q) {
  RIS_CHECK(grid_difference(current.grid, earlier.grid).empty());
  const auto& a = q == CompareQuantity::mean ? current.mean_power_w : current.speckled_power_w;
  const auto& b = q == CompareQuantity::mean ? earlier.mean_power_w : earlier.speckled_power_w;
  RIS_CHECK(a.size() == b.size());
  Difference d;
  d.lines = current.grid.lines;
  d.bins = current.grid.bins;
  d.db.reserve(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    d.db.push_back(static_cast<float>(pixel_difference_db(a[i], b[i])));
  }
  return d;
}

double default_range_db(const Difference& d) {
  std::vector<float> mag;
  mag.reserve(d.db.size());
  for (const float v : d.db) {
    if (std::isfinite(v)) mag.push_back(std::abs(v));
  }
  if (mag.empty()) return 1.0;
  const std::size_t k =
      std::min(mag.size() - 1, static_cast<std::size_t>(0.98 * double(mag.size())));
  std::nth_element(mag.begin(), mag.begin() + static_cast<std::ptrdiff_t>(k), mag.end());
  return std::max(1.0, std::ceil(double(mag[k])));
}

std::array<std::uint8_t, 3> difference_colour(double d_db, double range_db) {
  // t in [0, 10]: the ramp's classes, class 5 at 0 dB.
  const double t = std::clamp(5.0 + 5.0 * d_db / range_db, 0.0, 10.0);
  const int i = std::min(9, static_cast<int>(std::floor(t)));
  const double f = t - i;
  std::array<std::uint8_t, 3> rgb{};
  for (int c = 0; c < 3; ++c) {
    const double v = kRamp[i][c] + f * (kRamp[i + 1][c] - kRamp[i][c]);
    rgb[c] = static_cast<std::uint8_t>(std::lround(v));
  }
  return rgb;
}

nlohmann::json difference_key(double range_db) {
  nlohmann::json stops = nlohmann::json::array();
  for (int i = 0; i < 11; ++i) {
    stops.push_back(
        {{"db", range_db * (i - 5) / 5.0}, {"rgb", {kRamp[i][0], kRamp[i][1], kRamp[i][2]}}});
  }
  return stops;
}

std::vector<std::uint8_t> difference_png(const Difference& d, double range_db) {
  std::vector<std::uint8_t> rgba(d.db.size() * 4, 0);
  for (std::size_t i = 0; i < d.db.size(); ++i) {
    if (!std::isfinite(d.db[i])) continue;  // transparent
    const auto rgb = difference_colour(d.db[i], range_db);
    std::copy(rgb.begin(), rgb.end(), rgba.begin() + static_cast<std::ptrdiff_t>(4 * i));
    rgba[4 * i + 3] = 255;
  }
  return encode_png(rgba.data(), d.bins, d.lines, 4);
}

}  // namespace ris
