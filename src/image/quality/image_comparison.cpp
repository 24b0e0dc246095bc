#include "ris/image/image_comparison.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace ris {

namespace {

bool has(float v) {
  return v > 0.0f && v < 3.4e38f;
}

double pearson(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = double(x.size());
  const double mx = std::accumulate(x.begin(), x.end(), 0.0) / n;
  const double my = std::accumulate(y.begin(), y.end(), 0.0) / n;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxy += (x[i] - mx) * (y[i] - my);
    sxx += (x[i] - mx) * (x[i] - mx);
    syy += (y[i] - my) * (y[i] - my);
  }
  return sxx > 0.0 && syy > 0.0 ? sxy / std::sqrt(sxx * syy) : 0.0;
}

// Ranks from 0, ties given their mean rank.
std::vector<double> ranks(const std::vector<double>& v) {
  std::vector<std::size_t> order(v.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return v[i] < v[j]; });
  std::vector<double> r(v.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && v[order[j + 1]] == v[order[i]]) ++j;
    for (std::size_t k = i; k <= j; ++k) r[order[k]] = 0.5 * double(i + j);
    i = j + 1;
  }
  return r;
}

// b averaged over 5 x 5 pixels (only where all hold a finite value >= 0:
// a simulation's shadow is 0), in dB (-300 for 0); NaN else.
std::vector<double> smoothed_db(std::span<const float> b, int cols, int rows) {
  std::vector<double> out(b.size(), std::nan(""));
  for (int r = 2; r + 2 < rows; ++r) {
    for (int c = 2; c + 2 < cols; ++c) {
      double s = 0.0;
      bool all = true;
      for (int dr = -2; dr <= 2 && all; ++dr)
        for (int dc = -2; dc <= 2; ++dc) {
          const float v = b[static_cast<std::size_t>(r + dr) * cols + (c + dc)];
          all = all && v >= 0.0f && v < 3.4e38f;
          s += v;
        }
      if (all) {
        out[static_cast<std::size_t>(r) * cols + c] =
            s > 0.0 ? 10.0 * std::log10(s / 25.0) : -300.0;
      }
    }
  }
  return out;
}

}  // namespace

WindowAgreement window_agreement(std::span<const float> a, std::span<const float> b, int cols,
                                 int rows, int window) {
  WindowAgreement out;
  out.window = window;
  std::vector<double> x, y;
  for (int r0 = 0; r0 + window <= rows; r0 += window) {
    for (int c0 = 0; c0 + window <= cols; c0 += window) {
      double sa = 0.0, sb = 0.0;
      bool all = true;
      for (int r = r0; r < r0 + window && all; ++r)
        for (int c = c0; c < c0 + window; ++c) {
          const std::size_t i = static_cast<std::size_t>(r) * cols + c;
          all = all && has(a[i]) && has(b[i]);
          sa += a[i], sb += b[i];
        }
      if (!all) continue;
      x.push_back(10.0 * std::log10(sa / (window * window)));
      y.push_back(10.0 * std::log10(sb / (window * window)));
    }
  }
  out.blocks = static_cast<std::int64_t>(x.size());
  if (x.size() < 3) return out;
  out.pearson = pearson(x, y);
  out.spearman = pearson(ranks(x), ranks(y));
  double s = 0.0, s2 = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) s += y[i] - x[i], s2 += (y[i] - x[i]) * (y[i] - x[i]);
  out.bias_db = s / double(x.size());
  out.rms_db = std::sqrt(s2 / double(x.size()));
  return out;
}

double histogram_hellinger(std::span<const float> a, std::span<const float> b) {
  std::map<long, double> pa, pb;
  double na = 0.0, nb = 0.0;
  for (float v : a)
    if (has(v)) pa[std::lround(std::floor(10.0 * std::log10(v)))] += 1.0, na += 1.0;
  for (float v : b)
    if (has(v)) pb[std::lround(std::floor(10.0 * std::log10(v)))] += 1.0, nb += 1.0;
  if (na == 0.0 || nb == 0.0) return 1.0;
  double bc = 0.0;
  for (const auto& [k, n] : pa) {
    const auto it = pb.find(k);
    if (it != pb.end()) bc += std::sqrt((n / na) * (it->second / nb));
  }
  return std::sqrt(std::max(0.0, 1.0 - bc));
}

std::vector<CategoryBias> category_bias(std::span<const float> a, std::span<const float> b,
                                        std::span<const double> categories) {
  std::map<std::int64_t, std::pair<std::int64_t, double>> by;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double c = categories[i];
    if (!has(a[i]) || !has(b[i]) || !std::isfinite(c) || c < 0.0) continue;
    auto& [n, s] = by[std::llround(c)];
    ++n;
    s += 10.0 * std::log10(double(b[i]) / double(a[i]));
  }
  std::vector<CategoryBias> out;
  for (const auto& [c, ns] : by) out.push_back({c, ns.first, ns.second / double(ns.first)});
  return out;
}

MaskAgreement mask_agreement(std::span<const std::uint8_t> mask, std::uint8_t bit,
                             std::span<const float> b, int cols, int rows, bool dark) {
  const std::vector<double> s = smoothed_db(b, cols, rows);
  std::vector<double> valid;
  for (double v : s)
    if (std::isfinite(v)) valid.push_back(v);
  MaskAgreement out;
  if (valid.empty()) return out;
  const auto k = static_cast<std::size_t>((dark ? 0.10 : 0.90) * double(valid.size() - 1));
  std::nth_element(valid.begin(), valid.begin() + static_cast<std::ptrdiff_t>(k), valid.end());
  const double threshold = valid[k];
  std::int64_t inter = 0, uni = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (!std::isfinite(s[i])) continue;
    const bool m = (mask[i] & bit) != 0;
    const bool d = dark ? s[i] <= threshold : s[i] >= threshold;
    out.mask_pixels += m;
    out.image_pixels += d;
    inter += m && d;
    uni += m || d;
  }
  out.iou = uni > 0 ? double(inter) / double(uni) : 0.0;
  return out;
}

}  // namespace ris
