#include "ris/sim/point_target_irf.h"

#include <algorithm>
#include <cmath>
#include <span>

namespace ris {

namespace {
// Search for the peak within this many pixels of the predicted position, and
// cut this many pixels each side of it (enough for 8 sinc null spacings at
// two pixels per resolution cell).
constexpr int kSearchPx = 3;
constexpr int kHalfCutPx = 24;
}  // namespace

std::optional<IrfWindow> point_target_irf_window(const SlarImage& img, const PointReturn& pr) {
  const double pos = (pr.slant_range_m - img.range.near_m) / img.range.bin_m;
  if (!(pos >= 0.0 && pos < img.bins)) return std::nullopt;
  const int bin = static_cast<int>(pos);
  // measure_irf reads within kSearchPx of (line, bin), then kHalfCutPx
  // either side of the peak it finds.
  constexpr int reach = kSearchPx + kHalfCutPx;
  IrfWindow w;
  w.line0 = std::max(0, pr.line - reach);
  w.lines = std::min(img.lines - 1, pr.line + reach) - w.line0 + 1;
  w.bin0 = std::max(0, bin - reach);
  w.bins = std::min(img.bins - 1, bin + reach) - w.bin0 + 1;
  return w;
}

PointTargetIrf measure_point_target_in_window(const SlarImage& img, const PointReturn& pr,
                                              const IrfWindow& w,
                                              std::span<const float> window_power, bool coherent) {
  const int bin = static_cast<int>((pr.slant_range_m - img.range.near_m) / img.range.bin_m);
  // Inside the window every read of measure_irf lands where it would in the
  // whole image, and the window's edges are the image's where clipped.
  IrfMeasurement m = measure_irf(window_power, w.lines, w.bins, img.line_spacing_m, img.range.bin_m,
                                 pr.line - w.line0, bin - w.bin0, kSearchPx, kHalfCutPx,
                                 coherent ? IrfInterpolation::sinc : IrfInterpolation::linear);
  m.peak_line += w.line0;
  m.peak_bin += w.bin0;
  return {pr, m};
}

std::vector<PointTargetIrf> measure_point_targets(const SlarSimulation& sim,
                                                  const SlarPictures& pictures, bool coherent) {
  const SlarImage& img = sim.image;
  const std::span<const float> power =
      coherent ? std::span<const float>(pictures.speckled_power_w) : img.mean_power_w;
  std::vector<PointTargetIrf> out;
  std::vector<float> window;
  for (const PointReturn& pr : sim.point_returns) {
    const std::optional<IrfWindow> w = point_target_irf_window(img, pr);
    if (!w) continue;
    window.resize(static_cast<std::size_t>(w->lines) * static_cast<std::size_t>(w->bins));
    for (int l = 0; l < w->lines; ++l) {
      std::copy_n(power.data() + img.index(w->line0 + l, w->bin0), w->bins,
                  window.data() + static_cast<std::size_t>(l) * static_cast<std::size_t>(w->bins));
    }
    out.push_back(measure_point_target_in_window(img, pr, *w, window, coherent));
  }
  return out;
}

nlohmann::json point_target_irf_json(const std::vector<PointTargetIrf>& irfs,
                                     const SlarSimulation& sim, const std::string& targets_file,
                                     bool coherent) {
  nlohmann::json seen = nlohmann::json::array();
  for (const PointTargetIrf& t : irfs) {
    nlohmann::json j = irf_to_json(t.irf);
    j["slant_range_m"] = t.target.slant_range_m;
    j["along_track_m"] = t.target.along_m;
    j["rcs_m2"] = t.target.rcs_m2;
    seen.push_back(j);
  }
  return {{"file", targets_file},
          {"measured_on", coherent ? "coherent intensity" : "mean power before fading"},
          {"interpolation", coherent ? "sinc" : "linear"},
          {"seen", seen},
          {"hidden", sim.hidden_targets}};
}

}  // namespace ris
