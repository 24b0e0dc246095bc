#include "ris/image/impulse_response.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

namespace {

constexpr int kOversample = 32;

double to_db(double ratio) {
  return ratio > 0.0 ? 10.0 * std::log10(ratio) : -std::numeric_limits<double>::infinity();
}

std::vector<double> oversample(std::span<const double> cut, IrfInterpolation how) {
  const int n = static_cast<int>(cut.size());
  const int m = (n - 1) * kOversample + 1;
  std::vector<double> out(static_cast<std::size_t>(m));
  for (int q = 0; q < m; ++q) {
    const double x = double(q) / kOversample;
    if (how == IrfInterpolation::linear || q % kOversample == 0) {
      const int i = std::min(q / kOversample, n - 2);
      const double f = x - i;
      out[static_cast<std::size_t>(q)] =
          (1.0 - f) * cut[static_cast<std::size_t>(i)] + f * cut[static_cast<std::size_t>(i) + 1];
      continue;
    }
    double v = 0.0;
    for (int i = 0; i < n; ++i) {
      const double d = kPi * (x - i);
      v += cut[static_cast<std::size_t>(i)] * std::sin(d) / d;
    }
    out[static_cast<std::size_t>(q)] = v;
  }
  return out;
}

}  // namespace

IrfCut measure_irf_cut(std::span<const double> cut, double spacing_m, IrfInterpolation how) {
  RIS_CHECK(cut.size() >= 3);
  const std::vector<double> y = oversample(cut, how);
  const int m = static_cast<int>(y.size());
  // The peak near the middle (the brightest oversampled point within one
  // pixel of the centre sample).
  const int mid = (m - 1) / 2;
  int pk = mid;
  for (int q = std::max(0, mid - kOversample); q <= std::min(m - 1, mid + kOversample); ++q)
    if (y[static_cast<std::size_t>(q)] > y[static_cast<std::size_t>(pk)]) pk = q;
  const double peak = y[static_cast<std::size_t>(pk)];
  const double half = 0.5 * peak;
  // Half-power crossings, linear between oversampled points.
  auto crossing = [&](int dir) {
    int q = pk;
    while (q + dir >= 0 && q + dir < m && y[static_cast<std::size_t>(q + dir)] >= half) q += dir;
    if (q + dir < 0 || q + dir >= m) return double(q);
    const double a = y[static_cast<std::size_t>(q)], b = y[static_cast<std::size_t>(q + dir)];
    return q + dir * (a - half) / (a - b);
  };
  IrfCut c;
  c.width_m = (crossing(+1) - crossing(-1)) / kOversample * spacing_m;
  // Main lobe: to the first minimum each side.
  auto first_min = [&](int dir) {
    int q = pk;
    while (q + dir >= 0 && q + dir < m &&
           y[static_cast<std::size_t>(q + dir)] <= y[static_cast<std::size_t>(q)])
      q += dir;
    return q;
  };
  const int lo = first_min(-1), hi = first_min(+1);
  double main_lobe = 0.0, side = 0.0, side_peak = 0.0;
  for (int q = 0; q < m; ++q) {
    const double v = std::max(0.0, y[static_cast<std::size_t>(q)]);
    if (q >= lo && q <= hi) {
      main_lobe += v;
    } else {
      side += v;
      side_peak = std::max(side_peak, v);
    }
  }
  c.pslr_db = to_db(side_peak / peak);
  c.islr_db = to_db(side / main_lobe);
  return c;
}

IrfMeasurement measure_irf(std::span<const float> power, int lines, int bins, double line_spacing_m,
                           double bin_m, int line, int bin, int search_px, int half_length_px,
                           IrfInterpolation how) {
  RIS_CHECK(power.size() == static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins));
  IrfMeasurement r;
  const auto at = [&](int l, int b) {
    return double(power[static_cast<std::size_t>(l) * static_cast<std::size_t>(bins) +
                        static_cast<std::size_t>(b)]);
  };
  r.peak_line = std::clamp(line, 0, lines - 1);
  r.peak_bin = std::clamp(bin, 0, bins - 1);
  for (int l = std::max(0, line - search_px); l <= std::min(lines - 1, line + search_px); ++l)
    for (int b = std::max(0, bin - search_px); b <= std::min(bins - 1, bin + search_px); ++b) {
      const double v = at(l, b);
      if (std::isfinite(v) && v > at(r.peak_line, r.peak_bin)) {
        r.peak_line = l;
        r.peak_bin = b;
      }
    }
  r.peak_power_w = at(r.peak_line, r.peak_bin);
  // Symmetric cuts, clipped at the image edge.
  const int hr = std::min({half_length_px, r.peak_bin, bins - 1 - r.peak_bin});
  const int ha = std::min({half_length_px, r.peak_line, lines - 1 - r.peak_line});
  std::vector<double> cut_r, cut_a;
  for (int d = -hr; d <= hr; ++d) cut_r.push_back(at(r.peak_line, r.peak_bin + d));
  for (int d = -ha; d <= ha; ++d) cut_a.push_back(at(r.peak_line + d, r.peak_bin));
  for (double& v : cut_r)
    if (!std::isfinite(v)) v = 0.0;
  for (double& v : cut_a)
    if (!std::isfinite(v)) v = 0.0;
  if (cut_r.size() >= 3) r.range = measure_irf_cut(cut_r, bin_m, how);
  if (cut_a.size() >= 3) r.azimuth = measure_irf_cut(cut_a, line_spacing_m, how);
  r.pslr_db = std::max(r.range.pslr_db, r.azimuth.pslr_db);
  r.islr_db = std::max(r.range.islr_db, r.azimuth.islr_db);
  return r;
}

nlohmann::json irf_to_json(const IrfMeasurement& m) {
  const auto finite = [](double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
  };
  return {{"peak_line", m.peak_line},
          {"peak_bin", m.peak_bin},
          {"peak_power_w", m.peak_power_w},
          {"range_resolution_3db_m", m.range.width_m},
          {"azimuth_resolution_3db_m", m.azimuth.width_m},
          {"range_pslr_db", finite(m.range.pslr_db)},
          {"azimuth_pslr_db", finite(m.azimuth.pslr_db)},
          {"range_islr_db", finite(m.range.islr_db)},
          {"azimuth_islr_db", finite(m.azimuth.islr_db)},
          {"pslr_db", finite(m.pslr_db)},
          {"islr_db", finite(m.islr_db)}};
}

}  // namespace ris
