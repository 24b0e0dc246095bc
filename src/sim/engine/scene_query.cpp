#include "sim/engine/scene_query.h"

#include <algorithm>
#include <cstddef>
#include <tuple>
#include <utility>

#include "ris/util/error.h"
#include "sim/engine/slar_line_stages.h"

namespace ris::detail {

bool contribution_before(const LineContribution& a, const LineContribution& b) {
  return std::tie(a.line, a.bin, a.stage, a.source, a.from_line, a.seq) <
         std::tie(b.line, b.bin, b.stage, b.source, b.from_line, b.seq);
}

void PointTargetQuery::query(const LineQuery& q, std::vector<LineContribution>& out) const {
  LinePointTargets& t = targets_;
  const auto on_line =
      std::lower_bound(t.by_line.begin(), t.by_line.end(), q.line,
                       [](const PointCandidate& c, int l) { return c.ret.line < l; });
  for (auto it = on_line; it != t.by_line.end() && it->ret.line == q.line; ++it) {
    const std::size_t k = static_cast<std::size_t>(it - t.by_line.begin());
    if (!point_lit_on_samples(q.layout, q.first, q.n, q.s.flags.data(), q.s.height.data(), it->u_m,
                              it->h_m)) {
      continue;
    }
    // The point-target radar equation P = k G^2(beta) sigma / R^4 (MODEL.md).
    const PointReturn& pr = it->ret;
    const double r2 = pr.slant_range_m * pr.slant_range_m;
    const double power = q.ctx.k_radar * q.ctx.gain2->at(pr.look_rad) * pr.rcs_m2 / (r2 * r2);
    t.lit[k] = 1;
    t.power_w[k] = power;
    const double pos = (pr.slant_range_m - q.ctx.near_m) * q.ctx.inv_dr;
    if (!(pos >= 0.0 && pos < q.ctx.bins)) continue;
    out.push_back({q.line, static_cast<int>(pos), k, power});
  }
}

void query_line(std::span<const SceneQueryStage* const> stages, const LineQuery& q, double* acc,
                std::vector<LineContribution>& scratch, std::vector<LineContribution>& carried) {
  scratch.clear();
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const std::size_t before = scratch.size();
    stages[i]->query(q, scratch);
    for (std::size_t j = before; j < scratch.size(); ++j) {
      LineContribution& c = scratch[j];
      RIS_CHECK(c.bin >= 0 && c.bin < q.ctx.bins);
      c.stage = static_cast<int>(i);
      c.from_line = q.line;
      c.seq = static_cast<int>(j - before);
    }
  }
  if (scratch.empty()) return;
  // The line's own contributions in the fixed order; the others carried.
  const auto own = std::stable_partition(
      scratch.begin(), scratch.end(), [&](const LineContribution& c) { return c.line == q.line; });
  carried.insert(carried.end(), own, scratch.end());
  std::sort(scratch.begin(), own, contribution_before);
  for (auto it = scratch.begin(); it != own; ++it)
    acc[static_cast<std::size_t>(it->bin)] += it->power_w;
}

std::vector<LineContribution> add_carried_contributions(std::vector<LineContribution> carried,
                                                        int line0, int line1, double window_bins,
                                                        SlarLineProfiles& prof) {
  std::sort(carried.begin(), carried.end(), contribution_before);
  std::vector<LineContribution> elsewhere;
  SlarLineAccumulator row(prof.bins);
  for (std::size_t i = 0; i < carried.size();) {
    const int line = carried[i].line;
    std::size_t end = i;
    while (end < carried.size() && carried[end].line == line) ++end;
    if (line < line0 || line >= line1) {
      elsewhere.insert(elsewhere.end(), carried.begin() + static_cast<std::ptrdiff_t>(i),
                       carried.begin() + static_cast<std::ptrdiff_t>(end));
      i = end;
      continue;
    }
    std::fill(row.acc.begin(), row.acc.end(), 0.0);
    std::fill(row.acc_area.begin(), row.acc_area.end(), 0.0);
    for (; i < end; ++i) row.acc[static_cast<std::size_t>(carried[i].bin)] += carried[i].power_w;
    if (window_bins > 0.0) row.apply_range_window(window_bins);
    const std::size_t at = prof.index(line, 0);
    for (int b = 0; b < prof.bins; ++b) {
      const std::size_t bb = static_cast<std::size_t>(b);
      if (row.acc[bb] != 0.0) {
        prof.power_w[at + bb] = static_cast<float>(double(prof.power_w[at + bb]) + row.acc[bb]);
      }
    }
  }
  return elsewhere;
}

}  // namespace ris::detail
