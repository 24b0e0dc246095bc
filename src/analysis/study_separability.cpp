// Separability of categories at matched geometry: the closed forms and the
// per-bin and per-window statistics (ris/analysis/study_separability.h).
#include "ris/analysis/study_separability.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ris/util/error.h"

namespace ris {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Running sums of one category's calibrated intensity I and pixel incidence
// t (rad) in one bin.
struct Sums {
  std::int64_t n = 0;
  double sum = 0.0, sum2 = 0.0, looks = 0.0;
  double t = 0.0, t2 = 0.0, it = 0.0;  // sums of t, t^2, I t
  void add(double i, double theta, double l) {
    ++n;
    sum += i;
    sum2 += i * i;
    looks += l;
    t += theta;
    t2 += theta * theta;
    it += i * theta;
  }
  double mean() const { return sum / double(n); }
  double mean_t() const { return t / double(n); }
  // Sample variance of I / mean (the relative spread: speckle and trend).
  double relative_var() const {
    const double m = mean();
    return std::max(0.0, (sum2 - double(n) * m * m) / double(n - 1)) / (m * m);
  }
  // Standard error of ln(mean): s / (m sqrt n), s the sample deviation.
  double log_mean_error() const { return std::sqrt(relative_var() / double(n)); }
};

// The trend of I with incidence inside one bin, common to its categories
// (analysis of covariance): the pooled within-category slope of I / m_c on
// t, beta ~ d ln sigma0 / dt, and its variance. Categories are compared at
// the same incidence by ln m_c - beta (tbar_c - t0), so that a category
// lying at the bin's upper edge and one at its lower edge are not told apart
// by the slope of their common law (the null check's Muhleman law falls
// 0.4 dB per degree at 80 deg).
struct BinTrend {
  double beta = 0.0;
  double beta_var = 0.0;
};

BinTrend bin_trend(const Sums* s, std::size_t n, std::int64_t min_pixels) {
  double num = 0.0, den = 0.0, var_sum = 0.0, dof = 0.0;
  for (std::size_t c = 0; c < n; ++c) {
    const Sums& a = s[c];
    if (a.n < min_pixels || !(a.sum > 0.0)) continue;
    const double m = a.mean(), tb = a.mean_t();
    num += (a.it - a.sum * tb) / m;  // sum (I/m - 1)(t - tbar)
    den += a.t2 - double(a.n) * tb * tb;
    var_sum += a.relative_var() * double(a.n - 1);
    dof += double(a.n - 1);
  }
  BinTrend b;
  // Below ~1e-12 rad^2 of spread there is no within-category information
  // (every category at one incidence): no adjustment.
  if (den > 1e-12 && dof > 0.0) {
    b.beta = num / den;
    b.beta_var = var_sum / dof / den;
  }
  return b;
}

// A log ratio below this counts as zero when it has no sampling error
// (fading off and no variation inside the bin): float rounding only.
constexpr double kExactZeroLogRatio = 1e-6;

double z_score(double log_ratio, double sigma) {
  if (sigma > 0.0) return log_ratio / sigma;
  if (std::abs(log_ratio) < kExactZeroLogRatio) return 0.0;
  return std::copysign(std::numeric_limits<double>::infinity(), log_ratio);
}

PairBin pair_in_bin(int bin, std::uint16_t a, std::uint16_t b, const Sums& sa, const Sums& sb,
                    const BinTrend& trend) {
  PairBin pb;
  pb.bin = bin;
  pb.a = a;
  pb.b = b;
  pb.pixels_a = sa.n;
  pb.pixels_b = sb.n;
  // Both means taken to the pair's mean incidence t0 along the bin's trend.
  const double t0 = (sa.t + sb.t) / double(sa.n + sb.n);
  pb.mean_a = sa.mean() * std::exp(trend.beta * (t0 - sa.mean_t()));
  pb.mean_b = sb.mean() * std::exp(trend.beta * (t0 - sb.mean_t()));
  pb.looks = (sa.looks + sb.looks) / double(sa.n + sb.n);
  const double ea = sa.log_mean_error(), eb = sb.log_mean_error();
  const double dt = sa.mean_t() - sb.mean_t();
  pb.sigma_log = std::sqrt(ea * ea + eb * eb + trend.beta_var * dt * dt);
  pb.z = z_score(std::log(pb.mean_a / pb.mean_b), pb.sigma_log);
  pb.jm = jeffries_matusita(gamma_bhattacharyya(pb.mean_a, pb.mean_b, pb.looks));
  pb.jm_noise = jeffries_matusita(gamma_bhattacharyya(std::exp(pb.sigma_log), 1.0, pb.looks));
  return pb;
}

// Combines a pair's bins: inverse-variance weights for the log ratio and its
// z (a bin without sampling error counts with unit weight alone), pixel
// weights n_a n_b / (n_a + n_b) for JM.
PairSeparability summarise_pair(std::uint16_t a, std::uint16_t b, const std::vector<PairBin>& bins,
                                double z_critical) {
  PairSeparability s;
  s.a = a;
  s.b = b;
  double wsum = 0.0, wlog = 0.0, hsum = 0.0, hjm = 0.0, hnoise = 0.0;
  double exact_sum = 0.0;
  int exact = 0;
  for (const PairBin& p : bins) {
    if (p.a != a || p.b != b) continue;
    ++s.bins;
    const double log_ratio = std::log(p.mean_a / p.mean_b);
    if (p.sigma_log > 0.0) {
      const double w = 1.0 / (p.sigma_log * p.sigma_log);
      wsum += w;
      wlog += w * log_ratio;
    } else {
      exact_sum += log_ratio;
      ++exact;
    }
    const double h = double(p.pixels_a) * double(p.pixels_b) / double(p.pixels_a + p.pixels_b);
    hsum += h;
    hjm += h * p.jm;
    hnoise += h * p.jm_noise;
  }
  if (s.bins == 0) {
    s.delta_db = s.z = s.jm = s.jm_noise = kNaN;
    return s;
  }
  s.jm = hjm / hsum;
  s.jm_noise = hnoise / hsum;
  const double log_ratio = exact > 0 ? exact_sum / exact : wlog / wsum;
  s.delta_db = 10.0 / std::log(10.0) * log_ratio;
  s.z = exact > 0 ? z_score(log_ratio, 0.0) : wlog / std::sqrt(wsum);
  s.separated = std::abs(s.z) > z_critical;
  return s;
}

}  // namespace

double gamma_bhattacharyya(double mean_a, double mean_b, double looks) {
  RIS_CHECK(mean_a > 0.0 && mean_b > 0.0 && looks > 0.0);
  return looks * std::log((mean_a + mean_b) / (2.0 * std::sqrt(mean_a * mean_b)));
}

double jeffries_matusita(double bhattacharyya) {
  return 2.0 * (1.0 - std::exp(-bhattacharyya));
}

double normal_two_sided_quantile(double p) {
  RIS_CHECK(p > 0.0 && p < 1.0);
  // P(|N| > z) = erfc(z / sqrt 2), decreasing in z: bisection to 1e-12.
  double lo = 0.0, hi = 40.0;
  for (int i = 0; i < 200 && hi - lo > 1e-12; ++i) {
    const double mid = 0.5 * (lo + hi);
    (std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double muhleman_sigma0(double t) {
  const double d = std::sin(t) + 0.111 * std::cos(t);
  return 0.0118 * std::cos(t) / (d * d * d);
}

BandSeparability band_separability(std::span<const std::int32_t> labels, const IncidenceBins& ib,
                                   std::span<const double> calibrated,
                                   std::span<const double> looks,
                                   const std::vector<std::uint16_t>& categories,
                                   const SeparabilityOptions& options) {
  RIS_CHECK(labels.size() == ib.bin.size() && labels.size() == calibrated.size() &&
            labels.size() == looks.size() && labels.size() == ib.incidence_rad.size());
  std::vector<std::int32_t> slot(65536, -1);
  for (std::size_t i = 0; i < categories.size(); ++i) {
    slot[categories[i]] = static_cast<std::int32_t>(i);
  }
  const std::size_t nc = categories.size();
  std::vector<Sums> sums(nc * static_cast<std::size_t>(ib.count));
  for (std::size_t p = 0; p < labels.size(); ++p) {
    if (ib.bin[p] < 0 || labels[p] < 0 || !(calibrated[p] >= 0.0)) continue;
    const std::int32_t s = slot[static_cast<std::size_t>(labels[p])];
    if (s < 0) continue;
    Sums& a = sums[static_cast<std::size_t>(ib.bin[p]) * nc + static_cast<std::size_t>(s)];
    a.add(calibrated[p], ib.incidence_rad[p], looks[p]);
  }
  BandSeparability out;
  for (int k = 0; k < ib.count; ++k) {
    const Sums* in_bin = &sums[static_cast<std::size_t>(k) * nc];
    const BinTrend trend = bin_trend(in_bin, nc, options.min_pixels);
    for (std::size_t i = 0; i < nc; ++i) {
      const Sums& sa = sums[static_cast<std::size_t>(k) * nc + i];
      if (sa.n < options.min_pixels || !(sa.sum > 0.0)) continue;
      for (std::size_t j = i + 1; j < nc; ++j) {
        const Sums& sb = sums[static_cast<std::size_t>(k) * nc + j];
        if (sb.n < options.min_pixels || !(sb.sum > 0.0)) continue;
        out.bins.push_back(pair_in_bin(k, categories[i], categories[j], sa, sb, trend));
      }
    }
  }
  double score = 0.0, min_jm = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < nc; ++i) {
    for (std::size_t j = i + 1; j < nc; ++j) {
      PairSeparability s =
          summarise_pair(categories[i], categories[j], out.bins, options.z_critical);
      if (s.bins > 0) {
        ++out.compared_pairs;
        min_jm = std::min(min_jm, s.jm);
        out.max_abs_z = std::max(out.max_abs_z, std::abs(s.z));
        if (s.separated) {
          ++out.separated_pairs;
          score += s.jm;
        }
      }
      out.pairs.push_back(s);
    }
  }
  out.score = out.compared_pairs > 0 ? score / out.compared_pairs : 0.0;
  out.min_jm = out.compared_pairs > 0 ? min_jm : kNaN;
  return out;
}

}  // namespace ris
