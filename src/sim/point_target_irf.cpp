#include "ris/sim/point_target_irf.h"

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

std::vector<PointTargetIrf> measure_point_targets(const SlarSimulation& sim,
                                                  const SlarPictures& pictures, bool coherent) {
  const SlarImage& img = sim.image;
  const std::span<const float> power =
      coherent ? std::span<const float>(pictures.speckled_power_w) : img.mean_power_w;
  std::vector<PointTargetIrf> out;
  for (const PointReturn& pr : sim.point_returns) {
    const double pos = (pr.slant_range_m - img.range.near_m) / img.range.bin_m;
    if (!(pos >= 0.0 && pos < img.bins)) continue;
    const int bin = static_cast<int>(pos);
    out.push_back({pr, measure_irf(power, img.lines, img.bins, img.line_spacing_m, img.range.bin_m,
                                   pr.line, bin, kSearchPx, kHalfCutPx,
                                   coherent ? IrfInterpolation::sinc : IrfInterpolation::linear)});
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
