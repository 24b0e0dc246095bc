// Per-category sigma0(theta) from calibrated pixels: incidence bins, mean of
// linear sigma0 per bin, the table and its spread (see the header).
#include "ris/analysis/backscatter_fit.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

#include "ris/sensor/polarisation.h"

namespace ris {
namespace {

// 10 / ln 10: d(10 log10 m) / dm = this / m.
constexpr double kDbPerNeper = 4.342944819032518;

struct BinSums {
  std::int64_t n = 0;
  double sum = 0.0, sum2 = 0.0, sum_angle = 0.0;
};

struct CategorySums {
  std::int64_t pixels = 0;
  std::map<int, BinSums> bins;
};

void check_options(const BackscatterFitOptions& o) {
  if (!(o.bin_deg > 0.0 && o.bin_deg <= 30.0))
    throw std::invalid_argument(fmt::format("bin width: expected 0..30 deg, got {}", o.bin_deg));
  if (o.min_bin_pixels < 2)
    throw std::invalid_argument(
        fmt::format("pixels per bin: expected 2 or more, got {}", o.min_bin_pixels));
  if (o.min_bins < 1)
    throw std::invalid_argument(fmt::format("bins: expected 1 or more, got {}", o.min_bins));
}

// Solves the 3 x 3 system a x = b by Cramer's rule; false when singular.
bool solve3(const double a[3][3], const double b[3], double x[3]) {
  const auto det = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  const double d = det(a);
  if (!(std::abs(d) > 1e-300)) return false;
  for (int k = 0; k < 3; ++k) {
    double m[3][3];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) m[r][c] = c == k ? b[r] : a[r][c];
    x[k] = det(m) / d;
  }
  return true;
}

// Weighted least squares of dB on (1, t, t^2), t centred on the mean angle
// for conditioning, weights the bins' pixel counts; fewer than 3 bins or a
// singular system lower the degree (2 bins: a line; 1: a constant).
void fit_quadratic(CategoryFit& f) {
  double w_sum = 0.0, t_mean = 0.0;
  for (const auto& b : f.bins) w_sum += static_cast<double>(b.pixels);
  for (const auto& b : f.bins) t_mean += static_cast<double>(b.pixels) * b.angle_deg / w_sum;
  const int degree = std::min<int>(2, static_cast<int>(f.bins.size()) - 1);
  double a[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, rhs[3] = {0, 0, 0}, x[3] = {0, 0, 0};
  for (const auto& b : f.bins) {
    const double t = b.angle_deg - t_mean, w = static_cast<double>(b.pixels);
    const double p[3] = {1.0, t, t * t};
    const double db = 10.0 * std::log10(b.mean_linear);
    for (int r = 0; r < 3; ++r) {
      rhs[r] += w * p[r] * db;
      for (int c = 0; c < 3; ++c) a[r][c] += w * p[r] * p[c];
    }
  }
  for (int k = degree + 1; k < 3; ++k) {  // unused terms: identity rows
    for (int c = 0; c < 3; ++c) a[k][c] = a[c][k] = 0.0;
    a[k][k] = 1.0;
    rhs[k] = 0.0;
  }
  if (!solve3(a, rhs, x)) x[0] = rhs[0] / a[0][0], x[1] = x[2] = 0.0;
  // Back from centred t: c0 + c1 (t - m) + c2 (t - m)^2.
  f.quad[0] = x[0] - x[1] * t_mean + x[2] * t_mean * t_mean;
  f.quad[1] = x[1] - 2.0 * x[2] * t_mean;
  f.quad[2] = x[2];
  double ss = 0.0;
  for (auto& b : f.bins) {
    const double q = f.quad[0] + f.quad[1] * b.angle_deg + f.quad[2] * b.angle_deg * b.angle_deg;
    b.residual_db = 10.0 * std::log10(b.mean_linear) - q;
    ss += static_cast<double>(b.pixels) * b.residual_db * b.residual_db;
    f.max_residual_db = std::max(f.max_residual_db, std::abs(b.residual_db));
    b.table_db = f.bins.empty() ? 0.0 : 10.0 * std::log10(b.mean_linear);
  }
  f.rms_residual_db = std::sqrt(ss / w_sum);
}

CategoryFit fit_one(std::int32_t id, const CategorySums& s, const BackscatterFitOptions& o) {
  CategoryFit f;
  f.category = id;
  f.pixels = s.pixels;
  for (const auto& [k, b] : s.bins) {
    if (b.n < o.min_bin_pixels) continue;
    IncidenceBinFit bf;
    const double n = static_cast<double>(b.n);
    bf.pixels = b.n;
    bf.angle_deg = b.sum_angle / n;
    bf.mean_linear = b.sum / n;
    const double var = std::max(0.0, (b.sum2 - b.sum * b.sum / n) / (n - 1.0));
    bf.cv = std::sqrt(var) / bf.mean_linear;
    bf.se_db = kDbPerNeper * bf.cv / std::sqrt(n);
    f.used_pixels += b.n;
    f.bins.push_back(bf);
  }
  if (f.used_pixels < o.min_category_pixels || static_cast<int>(f.bins.size()) < o.min_bins) {
    f.reason = fmt::format(
        "{} pixels in {} incidence bins of {} or more pixels; at least {} pixels in {} bins "
        "needed",
        f.used_pixels, f.bins.size(), o.min_bin_pixels, o.min_category_pixels, o.min_bins);
    return f;
  }
  fit_quadratic(f);
  std::vector<double> se;
  for (const auto& b : f.bins) se.push_back(b.se_db);
  std::nth_element(se.begin(), se.begin() + static_cast<std::ptrdiff_t>(se.size() / 2), se.end());
  f.median_se_db = se[se.size() / 2];
  if (o.form == FitForm::quadratic)
    for (auto& b : f.bins) b.table_db -= b.residual_db;
  f.fitted = true;
  return f;
}

}  // namespace

std::vector<CategoryFit> fit_backscatter(std::span<const float> sigma0_linear,
                                         std::span<const float> incidence_deg,
                                         std::span<const std::int32_t> category,
                                         const BackscatterFitOptions& options) {
  check_options(options);
  if (sigma0_linear.size() != incidence_deg.size() || sigma0_linear.size() != category.size())
    throw std::invalid_argument(
        fmt::format("fit_backscatter: {} sigma0 values, {} incidence angles and {} categories",
                    sigma0_linear.size(), incidence_deg.size(), category.size()));
  std::map<std::int32_t, CategorySums> sums;
  for (std::size_t i = 0; i < category.size(); ++i) {
    const float s = sigma0_linear[i], t = incidence_deg[i];
    if (category[i] < 0 || !(s > 0.0f) || !std::isfinite(s) || !(t >= 0.0f && t < 90.0f)) continue;
    CategorySums& c = sums[category[i]];
    ++c.pixels;
    BinSums& b = c.bins[static_cast<int>(std::floor(t / options.bin_deg))];
    ++b.n;
    b.sum += s;
    b.sum2 += static_cast<double>(s) * s;
    b.sum_angle += t;
  }
  std::vector<CategoryFit> out;
  for (const auto& [id, s] : sums) out.push_back(fit_one(id, s, options));
  return out;
}

std::string backscatter_table_rows(const std::vector<CategoryFit>& fits, const RadarBand& band,
                                   const std::function<std::string(std::int32_t)>& name_of) {
  std::string out;
  for (const auto& f : fits) {
    if (!f.fitted) continue;
    const std::string name = name_of ? name_of(f.category) : std::string();
    if (!name.empty()) out += fmt::format("# category {}: {}\n", f.category, name);
  }
  for (const auto& f : fits) {
    if (!f.fitted) continue;
    double last = -1.0;
    for (const auto& b : f.bins) {
      // Angles are written to 1e-4 deg; a bin whose rounded angle does not
      // exceed the previous one (means within 1e-4 deg across a bin edge)
      // is skipped, as the table needs strictly increasing angles.
      const double a = std::round(b.angle_deg * 1e4) / 1e4;
      if (a <= last) continue;
      last = a;
      out += fmt::format("{},{:.10g},{},{:.4f},{:.4f}\n", f.category, band.frequency_hz / 1e9,
                         to_string(band.polarisation), a, b.table_db);
    }
  }
  return out;
}

std::string backscatter_table_csv(const std::vector<CategoryFit>& fits, const RadarBand& band,
                                  const std::function<std::string(std::int32_t)>& name_of,
                                  const std::string& provenance, bool clamp) {
  std::string out =
      "# sigma0 fitted from a calibrated image by ris calibrate (docs/calibrate.md)\n";
  if (!provenance.empty()) out += "# " + provenance + "\n";
  out +=
      "# per category: the mean of linear sigma0 in each local-incidence bin, at the bin's\n"
      "# mean incidence; ris interpolates linearly in dB between the rows\n";
  out += fmt::format("# clamp: {}\n", clamp ? "true" : "false");
  out += "category,frequency_ghz,polarisation,angle_deg,sigma0_db\n";
  return out + backscatter_table_rows(fits, band, name_of);
}

}  // namespace ris
