#include "ris/image/compare_report.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdint>

#include "ris/image/image_comparison.h"
#include "ris/image/image_registration.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

constexpr int kWindows[] = {1, 3, 5, 9};

// b(x + s) on a's grid, bilinear between b's pixel centres (NaN where any of
// the four is missing or outside).
std::vector<float> shifted(std::span<const float> b, int cols, int rows, double sx, double sy) {
  if (sx == 0.0 && sy == 0.0) return {b.begin(), b.end()};
  std::vector<float> out(b.size(), NAN);
  for (int r = 0; r < rows; ++r) {
    const double y = r + sy;
    const int y0 = static_cast<int>(std::floor(y));
    const double fy = y - y0;
    if (y0 < 0 || y0 + 1 >= rows) continue;
    for (int c = 0; c < cols; ++c) {
      const double x = c + sx;
      const int x0 = static_cast<int>(std::floor(x));
      const double fx = x - x0;
      if (x0 < 0 || x0 + 1 >= cols) continue;
      const auto at = [&](int yy, int xx) {
        return double(b[static_cast<std::size_t>(yy) * cols + xx]);
      };
      const double v = (1 - fy) * ((1 - fx) * at(y0, x0) + fx * at(y0, x0 + 1)) +
                       fy * ((1 - fx) * at(y0 + 1, x0) + fx * at(y0 + 1, x0 + 1));
      out[static_cast<std::size_t>(r) * cols + c] = static_cast<float>(v);
    }
  }
  return out;
}

nlohmann::json agreement_json(std::span<const float> a, std::span<const float> b, int cols,
                              int rows) {
  nlohmann::json j = nlohmann::json::array();
  for (int w : kWindows) {
    const WindowAgreement g = window_agreement(a, b, cols, rows, w);
    j.push_back({{"window", w},
                 {"blocks", g.blocks},
                 {"pearson", g.pearson},
                 {"spearman", g.spearman},
                 {"bias_db", g.bias_db},
                 {"rms_db", g.rms_db}});
  }
  return j;
}

}  // namespace

std::vector<float> intensity_to_db(std::span<const float> v) {
  std::vector<float> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    out[i] = v[i] > 0.0f && std::isfinite(v[i]) ? 10.0f * std::log10(v[i]) : NAN;
  return out;
}

CompareReport compare_measures(std::span<const float> simulated, std::span<const float> real,
                               int cols, int rows, const CompareRequest& request) {
  if (request.max_shift_px < 1) {
    throw InputError("", "max_shift",
                     fmt::format("expected 1 or more, got {}", request.max_shift_px));
  }
  const std::size_t n = static_cast<std::size_t>(cols) * static_cast<std::size_t>(rows);
  const auto check = [&](std::span<const double> r, const char* key) {
    if (!r.empty() && r.size() != n) {
      throw InputError(
          "", key, fmt::format("{} values, the simulated image has {} x {}", r.size(), cols, rows));
    }
  };
  check(request.categories, "categories");
  check(request.mask, "mask");
  check(request.local_incidence_deg, "local_incidence");
  if (simulated.size() != n || real.size() != n) {
    throw InputError("", "real", fmt::format("expected two images of {} x {} pixels", cols, rows));
  }
  CompareReport rep;
  nlohmann::json& out = rep.measures;
  out = nlohmann::json::object();

  // Co-registration of the dB images; the real image moved onto the simulation.
  rep.real_aligned.assign(real.begin(), real.end());
  if (request.register_images) {
    RegistrationRule rule;
    rule.max_shift_px = request.max_shift_px;
    const ImageRegistration reg =
        register_images(intensity_to_db(simulated), intensity_to_db(real), cols, rows, rule);
    out["registration"] = {{"shift_x_px", reg.shift_x_px},
                           {"shift_y_px", reg.shift_y_px},
                           {"peak_z", reg.peak_z},
                           {"peak_correlation", reg.peak_correlation},
                           {"peak_to_sidelobe", reg.peak_to_sidelobe},
                           {"min_z", rule.min_z},
                           {"looks", reg.looks},
                           {"levels", reg.levels}};
    rep.real_aligned = shifted(real, cols, rows, reg.shift_x_px, reg.shift_y_px);
  }
  const std::vector<float>& aligned = rep.real_aligned;
  out["agreement"] = agreement_json(simulated, aligned, cols, rows);
  out["histogram_hellinger"] = histogram_hellinger(simulated, aligned);

  if (!request.categories.empty()) {
    nlohmann::json cj = nlohmann::json::array();
    for (const CategoryBias& b : category_bias(simulated, aligned, request.categories))
      cj.push_back({{"category", b.category}, {"pixels", b.pixels}, {"bias_db", b.bias_db}});
    out["category_bias"] = cj;
  }
  if (!request.mask.empty()) {
    std::vector<std::uint8_t> bits;
    bits.reserve(n);
    for (double v : request.mask)
      bits.push_back(std::isfinite(v) ? static_cast<std::uint8_t>(v) : 0);
    const MaskAgreement sh = mask_agreement(bits, 1, aligned, cols, rows, true);
    const MaskAgreement lo = mask_agreement(bits, 2, aligned, cols, rows, false);
    out["masks"] = {{"shadow_vs_dark_iou", sh.iou},
                    {"shadow_pixels", sh.mask_pixels},
                    {"layover_vs_bright_iou", lo.iou},
                    {"layover_pixels", lo.mask_pixels}};
  }
  if (!request.local_incidence_deg.empty()) {
    // Baselines from the geometry alone: cos(theta_l) and Muhleman's
    // sigma0 = 0.0133 cos / (sin + 0.1 cos)^3 (docs/backscatter.md).
    const std::span<const double> li = request.local_incidence_deg;
    std::vector<float> cosine(n, NAN), muhleman(n, NAN);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = deg_to_rad(li[i]);
      if (!(std::isfinite(t) && t >= 0.0 && t < kPi / 2)) continue;
      cosine[i] = static_cast<float>(std::cos(t));
      const double d = std::sin(t) + 0.1 * std::cos(t);
      muhleman[i] = static_cast<float>(0.0133 * std::cos(t) / (d * d * d));
    }
    out["baselines"] = {{"cos_local_incidence", agreement_json(cosine, aligned, cols, rows)},
                        {"muhleman", agreement_json(muhleman, aligned, cols, rows)}};
  }
  return rep;
}

}  // namespace ris
