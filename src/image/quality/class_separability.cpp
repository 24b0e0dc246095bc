#include "ris/image/class_separability.h"

#include <cmath>
#include <map>

namespace ris {

std::vector<CategoryStatistics> category_statistics(const IntensityView& img,
                                                    std::span<const double> categories) {
  struct Sums {
    std::int64_t n = 0;
    double db = 0.0, db2 = 0.0, intensity = 0.0;
  };
  std::map<std::int64_t, Sums> by;
  const std::size_t n = static_cast<std::size_t>(img.cols) * static_cast<std::size_t>(img.rows);
  for (std::size_t i = 0; i < n; ++i) {
    const double c = categories[i];
    if (!img.usable(i) || !std::isfinite(c) || c < 0.0) continue;
    Sums& s = by[static_cast<std::int64_t>(std::llround(c))];
    const double v = img.intensity[i];
    const double db = 10.0 * std::log10(v);
    ++s.n;
    s.db += db;
    s.db2 += db * db;
    s.intensity += v;
  }
  std::vector<CategoryStatistics> out;
  for (const auto& [c, s] : by) {
    if (s.n < 2) continue;
    CategoryStatistics st;
    st.category = c;
    st.pixels = s.n;
    const double k = double(s.n);
    st.mean_db = s.db / k;
    st.std_db = std::sqrt(std::max(0.0, (s.db2 - s.db * s.db / k) / (k - 1.0)));
    st.mean_intensity_db = 10.0 * std::log10(s.intensity / k);
    out.push_back(st);
  }
  return out;
}

Separability separability(const CategoryStatistics& a, const CategoryStatistics& b) {
  Separability s;
  s.a = a.category;
  s.b = b.category;
  s.contrast_db = a.mean_intensity_db - b.mean_intensity_db;
  // Spreads floored at 0.01 dB: a noise-free image's classes are points.
  const double va = std::max(a.std_db, 0.01) * std::max(a.std_db, 0.01);
  const double vb = std::max(b.std_db, 0.01) * std::max(b.std_db, 0.01);
  const double d = a.mean_db - b.mean_db;
  s.bhattacharyya =
      d * d / (4.0 * (va + vb)) + 0.5 * std::log((va + vb) / (2.0 * std::sqrt(va * vb)));
  s.jeffries_matusita = 2.0 * (1.0 - std::exp(-s.bhattacharyya));
  return s;
}

}  // namespace ris
