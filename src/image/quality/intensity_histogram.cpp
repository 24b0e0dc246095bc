#include "ris/image/intensity_histogram.h"

#include <algorithm>
#include <cmath>

#include "ris/util/error.h"

namespace ris {

IntensityHistogram intensity_histogram(const IntensityView& img) {
  std::vector<float> db;
  const std::size_t n = static_cast<std::size_t>(img.cols) * static_cast<std::size_t>(img.rows);
  db.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    if (img.usable(i)) db.push_back(static_cast<float>(10.0 * std::log10(img.intensity[i])));
  if (db.empty()) {
    throw InputError("image", "pixels", "no pixel holds a finite intensity above zero");
  }
  IntensityHistogram h;
  h.pixels = static_cast<std::int64_t>(db.size());
  // Percentiles by rank (nearest rank, as numpy's 'lower').
  const auto pct = [&](double p) {
    const auto k = static_cast<std::size_t>(std::floor(p / 100.0 * double(db.size() - 1)));
    std::nth_element(db.begin(), db.begin() + static_cast<std::ptrdiff_t>(k), db.end());
    return double(db[k]);
  };
  h.p1_db = pct(1.0);
  h.p50_db = pct(50.0);
  h.p99_db = pct(99.0);
  const auto [lo, hi] = std::minmax_element(db.begin(), db.end());
  // 1 dB bins from the floor of the lowest value, at most 300 (values beyond
  // counted in the last bin).
  h.first_bin_db = std::floor(*lo);
  const int bins = std::clamp(static_cast<int>(std::floor(*hi - h.first_bin_db)) + 1, 1, 300);
  h.counts.assign(static_cast<std::size_t>(bins), 0);
  for (const float v : db) {
    const int b = std::min(bins - 1, static_cast<int>(std::floor(v - h.first_bin_db)));
    ++h.counts[static_cast<std::size_t>(b)];
  }
  return h;
}

}  // namespace ris
