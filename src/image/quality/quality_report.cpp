#include "ris/image/quality_report.h"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "ris/image/class_separability.h"
#include "ris/image/edge_sharpness.h"
#include "ris/image/impulse_response.h"
#include "ris/image/intensity_histogram.h"
#include "ris/util/error.h"

namespace ris {

std::vector<std::uint8_t> quality_mask_bits(std::span<const double> values) {
  std::vector<std::uint8_t> mask;
  mask.reserve(values.size());
  for (const double v : values)
    mask.push_back(std::isfinite(v) ? static_cast<std::uint8_t>(v) : std::uint8_t{4});
  return mask;
}

nlohmann::json quality_measures(const IntensityView& view, const QualityRequest& request) {
  if (request.window < 4) {
    throw InputError("", "window",
                     fmt::format("expected 4 or more pixels, got {}", request.window));
  }
  for (const PixelBox& b : request.regions) {
    if (b.cols <= 0 || b.rows <= 0) {
      throw InputError("", "regions",
                       fmt::format("a box needs a size above 0, got {},{},{},{}", b.col0, b.row0,
                                   b.cols, b.rows));
    }
  }
  for (const auto& [line, bin] : request.targets) {
    if (line < 0 || line >= view.rows || bin < 0 || bin >= view.cols) {
      throw InputError("", "target",
                       fmt::format("line {} bin {} is outside the {} x {} image", line, bin,
                                   view.rows, view.cols));
    }
  }
  nlohmann::json out;

  // Speckle over the given boxes or the automatic homogeneous windows.
  const bool automatic = request.regions.empty();
  const std::vector<PixelBox> boxes =
      automatic ? homogeneous_windows(view, HomogeneousRule{request.window, 3.0}) : request.regions;
  const SpeckleSummary s = pooled_speckle(view, boxes);
  out["speckle"] = {{"enl", s.enl},
                    {"cv", s.cv},
                    {"radiometric_resolution_db", s.radiometric_resolution_db},
                    {"regions", s.regions},
                    {"pixels", s.pixels},
                    {"regions_from", automatic ? fmt::format("automatic: {} x {} windows",
                                                             request.window, request.window)
                                               : std::string("--regions")}};

  const IntensityHistogram h = intensity_histogram(view);
  out["histogram"] = {{"pixels", h.pixels},
                      {"p1_db", h.p1_db},
                      {"p50_db", h.p50_db},
                      {"p99_db", h.p99_db},
                      {"dynamic_range_db", h.dynamic_range_db()},
                      {"first_bin_db", h.first_bin_db},
                      {"counts", h.counts}};

  if (!request.categories.empty()) {
    const std::vector<CategoryStatistics> stats = category_statistics(view, request.categories);
    nlohmann::json cj = nlohmann::json::array(), pj = nlohmann::json::array();
    for (const CategoryStatistics& c : stats) {
      cj.push_back({{"category", c.category},
                    {"pixels", c.pixels},
                    {"mean_db", c.mean_db},
                    {"std_db", c.std_db},
                    {"mean_intensity_db", c.mean_intensity_db}});
    }
    for (std::size_t i = 0; i < stats.size(); ++i) {
      for (std::size_t j = i + 1; j < stats.size(); ++j) {
        const Separability p = separability(stats[i], stats[j]);
        pj.push_back({{"a", p.a},
                      {"b", p.b},
                      {"contrast_db", p.contrast_db},
                      {"bhattacharyya", p.bhattacharyya},
                      {"jeffries_matusita", p.jeffries_matusita}});
      }
    }
    out["categories"] = cj;
    out["pairs"] = pj;
  }

  if (!view.mask.empty()) {
    const EdgeSharpness e = edge_sharpness(view.intensity, view.mask, view.cols, view.rows,
                                           static_cast<std::uint8_t>(request.mask_bit));
    out["edges"] = {{"bit", request.mask_bit},    {"edges", e.edges},
                    {"width_px", e.width_px},     {"lit_level", e.lit_level},
                    {"dark_level", e.dark_level}, {"mean_profile", e.mean_profile}};
  }

  if (!request.targets.empty()) {
    nlohmann::json tj = nlohmann::json::array();
    for (const auto& [line, bin] : request.targets) {
      const IrfMeasurement m =
          measure_irf(view.intensity, view.rows, view.cols, request.line_spacing_m,
                      request.range_bin_m, line, bin, 3, 24, IrfInterpolation::sinc);
      nlohmann::json j = irf_to_json(m);
      j["line"] = line;
      j["bin"] = bin;
      tj.push_back(j);
    }
    out["targets"] = tj;
  }
  return out;
}

}  // namespace ris
