#include "sim/stream/slar_stream_targets.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <utility>

#include "ris/geometry/terrain_sample.h"
#include "ris/util/error.h"

namespace ris::detail {

void pack_block_targets(const BlockTargets& t, std::vector<char>& out) {
  const auto put = [&](const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    out.insert(out.end(), c, c + n);
  };
  const std::size_t n = t.candidate.size();
  RIS_CHECK(t.lit.size() == n && t.power_w.size() == n);
  put(&n, sizeof(n));
  put(t.candidate.data(), n * sizeof(std::int32_t));
  put(t.lit.data(), n);
  put(t.power_w.data(), n * sizeof(double));
}

BlockTargets unpack_block_targets(const char*& p, const char* end) {
  const auto get = [&](void* to, std::size_t bytes) {
    RIS_CHECK(std::size_t(end - p) >= bytes);
    std::memcpy(to, p, bytes);
    p += bytes;
  };
  BlockTargets t;
  std::size_t n = 0;
  get(&n, sizeof(n));
  t.candidate.resize(n);
  t.lit.resize(n);
  t.power_w.resize(n);
  get(t.candidate.data(), n * sizeof(std::int32_t));
  get(t.lit.data(), n);
  get(t.power_w.data(), n * sizeof(double));
  return t;
}

double streamed_terrain_height(const SceneStreamReader& in, double x_m, double y_m) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const Scene& s = in.grid();
  // As bilinear_terrain_sample: the same cells and weights, summed in the
  // same order, from the 2 x 2 cells (fewer on a scene one cell wide or
  // tall) read from the file.
  const auto [cf, rf] = s.grid_from_world(x_m, y_m);
  if (!(cf >= 0.0 && cf <= s.cols && rf >= 0.0 && rf <= s.rows)) return kNaN;
  const BilinearCells<std::size_t> b = bilinear_cells<std::size_t>(s.rows, s.cols, cf, rf);
  const std::size_t cols = static_cast<std::size_t>(s.cols);
  const int row0 = static_cast<int>(b.cell00 / cols), col0 = static_cast<int>(b.cell00 % cols);
  const int rows_n = b.step_row ? 2 : 1, cols_n = b.step_col ? 2 : 1;
  float z[4] = {};
  std::uint16_t cat[4] = {};
  std::uint8_t ok[4] = {};
  in.read(row0, rows_n, col0, cols_n, z, cat, ok);
  // The four cells' places in the window (r0, c0), (r0, c1), (r1, c0), (r1, c1).
  const int at[4] = {0, cols_n - 1, (rows_n - 1) * cols_n, (rows_n - 1) * cols_n + cols_n - 1};
  float h = 0.0f;
  for (int k = 0; k < 4; ++k) {
    const float w = b.weight[k];
    if (!(w > 0.0f)) continue;
    if (!ok[at[k]]) return kNaN;  // touches no data
    h += w * z[at[k]];
  }
  return double(h);
}

std::vector<double> streamed_target_heights(const std::vector<PointTarget>& targets,
                                            const SceneStreamReader& in) {
  // check_point_targets_on_scene's checks and messages (the height read
  // off the scene is NaN, without a read).
  std::vector<double> base(targets.size());
  for (std::size_t k = 0; k < targets.size(); ++k) {
    base[k] = streamed_terrain_height(in, targets[k].x_m, targets[k].y_m);
    check_point_target_on_scene(targets[k], in.grid(), base[k]);
  }
  return base;
}

StreamTargets::StreamTargets(const std::vector<PointTarget>& targets, std::string targets_file,
                             const SceneStreamReader& in, const SlarGeometry& g,
                             const SlarImage& img)
    : targets_(targets), file_(std::move(targets_file)), bins_(img.bins) {
  const std::vector<double> base = streamed_target_heights(targets, in);
  // point_candidates, with the heights read above.
  const double H = g.altitude_m;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const PointTarget& t = targets[k];
    const auto [s, u] = g.track.along_cross(t.x_m, t.y_m);
    const int line = static_cast<int>(std::floor(s / g.line_spacing_m));
    const double h = base[k] + t.height_m;
    if (!(line >= 0 && line < g.lines && u > 0.0 && std::isfinite(h) && h < H)) continue;
    candidates_.push_back(point_candidate(k, line, s, u, h, H, t.rcs_m2));
  }
  lit_.assign(candidates_.size(), 0);
  power_w_.assign(candidates_.size(), 0.0);
  for (const PointCandidate& c : candidates_) {
    windows_.push_back(point_target_irf_window(img, c.ret));
    window_power_.emplace_back(windows_.back() ? std::size_t(windows_.back()->lines) *
                                                     std::size_t(windows_.back()->bins)
                                               : 0);
  }
}

std::optional<LinePointTargets> StreamTargets::candidates_on_lines(int l0, int l1) const {
  std::vector<PointCandidate> on;
  for (const PointCandidate& c : candidates_)
    if (c.ret.line >= l0 && c.ret.line < l1) on.push_back(c);
  if (on.empty()) return std::nullopt;
  return LinePointTargets(std::move(on));
}

BlockTargets StreamTargets::block_result(const LinePointTargets& t) const {
  BlockTargets b;
  for (std::size_t k = 0; k < t.by_line.size(); ++k) {
    // Candidates are in target order, one per target.
    const auto it = std::lower_bound(
        candidates_.begin(), candidates_.end(), t.by_line[k].target,
        [](const PointCandidate& c, std::size_t target) { return c.target < target; });
    RIS_CHECK(it != candidates_.end() && it->target == t.by_line[k].target);
    b.candidate.push_back(static_cast<std::int32_t>(it - candidates_.begin()));
    b.lit.push_back(t.lit[k]);
    b.power_w.push_back(t.power_w[k]);
  }
  return b;
}

void StreamTargets::add(const BlockTargets& b) {
  for (std::size_t k = 0; k < b.candidate.size(); ++k) {
    const auto c = static_cast<std::size_t>(b.candidate[k]);
    RIS_CHECK(c < candidates_.size());
    lit_[c] = b.lit[k];
    power_w_[c] = b.power_w[k];
  }
}

void StreamTargets::observe(int k0, int n, const float* power) {
  for (std::size_t c = 0; c < windows_.size(); ++c) {
    if (!windows_[c]) continue;
    const IrfWindow& w = *windows_[c];
    const int l_a = std::max(k0, w.line0), l_b = std::min(k0 + n, w.line0 + w.lines);
    for (int l = l_a; l < l_b; ++l) {
      std::copy_n(power + std::size_t(l - k0) * std::size_t(bins_) + std::size_t(w.bin0), w.bins,
                  window_power_[c].data() + std::size_t(l - w.line0) * std::size_t(w.bins));
    }
  }
}

void StreamTargets::finish(SlarSimulation& sim) const {
  // As form_slar_image_fused: the powers of the lit ones in candidate
  // (target) order, the returns and hidden names from seen_point_returns.
  sim.image.point_power_w.clear();
  for (std::size_t c = 0; c < candidates_.size(); ++c)
    if (lit_[c]) sim.image.point_power_w.push_back(power_w_[c]);
  sim.hidden_targets.clear();
  sim.point_returns = seen_point_returns(targets_, candidates_, lit_, &sim.hidden_targets);
}

std::vector<PointTargetIrf> StreamTargets::measure(const SlarSimulation& sim, bool coherent) const {
  // measure_point_targets's order: the seen returns (lit candidates).
  std::vector<PointTargetIrf> out;
  for (std::size_t c = 0; c < candidates_.size(); ++c) {
    if (!lit_[c] || !windows_[c]) continue;
    out.push_back(measure_point_target_in_window(sim.image, candidates_[c].ret, *windows_[c],
                                                 window_power_[c], coherent));
  }
  return out;
}

nlohmann::json StreamTargets::metadata(const std::vector<PointTargetIrf>& irfs,
                                       const SlarSimulation& sim, bool coherent) const {
  return point_target_irf_json(irfs, sim, file_, coherent);
}

}  // namespace ris::detail
