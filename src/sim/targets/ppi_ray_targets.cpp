#include "sim/targets/ppi_ray_targets.h"

#include <cmath>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris::detail {

namespace {

// Angle difference wrapped to [-pi, pi).
double wrap_pi(double a) {
  return a - 2.0 * kPi * std::floor((a + kPi) / (2.0 * kPi));
}

}  // namespace

bool azimuth_on_ray(const PpiGeometry& pg, int k, double alpha) {
  const double d = wrap_pi(alpha - pg.azimuth_rad(k));
  return d >= -0.5 * pg.ray_spacing_rad && d < 0.5 * pg.ray_spacing_rad;
}

std::vector<PointCandidate> ray_candidates(const std::vector<PointTarget>& targets,
                                           const std::vector<double>& base_m, const PpiGeometry& pg,
                                           std::vector<std::size_t>& target_of) {
  RIS_CHECK(base_m.size() == targets.size());
  std::vector<PointCandidate> out;
  const SlarGeometry& g = pg.rays;
  const double H = pg.altitude_m;
  for (std::size_t t = 0; t < targets.size(); ++t) {
    const PointTarget& pt = targets[t];
    const double dx = pt.x_m - pg.site_x_m, dy = pt.y_m - pg.site_y_m;
    const double u = std::hypot(dx, dy);
    const double alpha = std::atan2(dx, dy);
    const double h = base_m[t] + pt.height_m;
    for (int k = 0; k < g.lines; ++k) {
      if (!azimuth_on_ray(pg, k, alpha)) continue;
      if (!(u > 0.0)) continue;
      out.push_back(point_candidate(out.size(), k, alpha, u, h, H, pt.rcs_m2));
      target_of.push_back(t);
    }
  }
  return out;
}

void fold_ray_targets(const std::vector<PointTarget>& targets,
                      const std::vector<PointCandidate>& candidates,
                      const std::vector<std::size_t>& target_of,
                      const std::vector<std::uint8_t>& lit, const std::vector<double>& power_w,
                      std::vector<PointReturn>& returns, std::vector<double>& point_power_w,
                      std::vector<std::string>& hidden) {
  RIS_CHECK(lit.size() == candidates.size() && power_w.size() == candidates.size() &&
            target_of.size() == candidates.size());
  std::vector<std::uint8_t> seen(targets.size(), 0);
  // Candidates are in target and ray order (their own index).
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    if (!lit[c]) continue;
    returns.push_back(candidates[c].ret);
    point_power_w.push_back(power_w[c]);
    seen[target_of[c]] = 1;
  }
  for (std::size_t t = 0; t < targets.size(); ++t) {
    if (!seen[t]) hidden.push_back(targets[t].name);
  }
}

}  // namespace ris::detail
