#include "ris/image/edge_sharpness.h"

#include <cmath>

#include "ris/util/error.h"

namespace ris {

namespace {

// Where the profile first falls through `level` (linear between samples),
// in pixels from the edge; NaN when it never does.
double crossing(const std::vector<double>& p, int half, double level) {
  for (std::size_t k = 1; k < p.size(); ++k) {
    if (p[k - 1] >= level && p[k] < level) {
      const double t = (p[k - 1] - level) / (p[k - 1] - p[k]);
      return double(k) - 1.0 + t - half;
    }
  }
  return std::nan("");
}

}  // namespace

EdgeSharpness edge_sharpness(std::span<const float> intensity, std::span<const std::uint8_t> mask,
                             int cols, int rows, std::uint8_t bit, int half_px) {
  RIS_CHECK(half_px >= 4);
  EdgeSharpness out;
  std::vector<double> sum(static_cast<std::size_t>(2 * half_px), 0.0);
  std::vector<double> profile(sum.size());
  for (int r = 0; r < rows; ++r) {
    const std::size_t row = static_cast<std::size_t>(r) * static_cast<std::size_t>(cols);
    for (int c = half_px; c + half_px <= cols; ++c) {
      const bool before = (mask[row + c - 1] & bit) != 0, after = (mask[row + c] & bit) != 0;
      if (before == after) continue;
      // Lit first: a shadow -> lit edge is read backwards.
      bool whole = true;
      for (int k = -half_px; k < half_px; ++k) {
        const int cc = before ? c - 1 - k : c + k;
        const float v = intensity[row + static_cast<std::size_t>(cc)];
        whole = whole && std::isfinite(v);
        profile[static_cast<std::size_t>(k + half_px)] = v;
      }
      if (!whole) continue;
      for (std::size_t k = 0; k < sum.size(); ++k) sum[k] += profile[k];
      ++out.edges;
    }
  }
  if (out.edges == 0) {
    throw InputError("mask", "edges",
                     "no edge of the mask has a whole intensity profile across it");
  }
  out.mean_profile.resize(sum.size());
  for (std::size_t k = 0; k < sum.size(); ++k) out.mean_profile[k] = sum[k] / out.edges;
  const std::size_t q = sum.size() / 4;
  for (std::size_t k = 0; k < q; ++k) {
    out.lit_level += out.mean_profile[k] / double(q);
    out.dark_level += out.mean_profile[sum.size() - 1 - k] / double(q);
  }
  const double span = out.lit_level - out.dark_level;
  const double x90 = crossing(out.mean_profile, half_px, out.dark_level + 0.9 * span);
  const double x10 = crossing(out.mean_profile, half_px, out.dark_level + 0.1 * span);
  out.width_px = x10 - x90;
  return out;
}

}  // namespace ris
