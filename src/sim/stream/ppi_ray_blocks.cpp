#include "sim/stream/ppi_ray_blocks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "ris/util/error.h"
#include "sim/sources/polar_lines.h"

namespace ris::detail {

namespace {

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

}  // namespace

void pack_ray_block(const RayBlock& k, std::vector<char>& out) {
  const auto put = [&](const void* p, std::size_t n) {
    const char* c = static_cast<const char*>(p);
    out.insert(out.end(), c, c + n);
  };
  const int head[5] = {k.k0, k.k1, k.prof.line0, k.prof.lines, k.prof.bins};
  put(head, sizeof(head));
  put(&k.counts, sizeof(RayCounts));
  const std::size_t np = k.prof.power_w.size();
  put(k.prof.power_w.data(), np * sizeof(float));
  put(k.prof.area_m2.data(), np * sizeof(float));
  put(k.prof.touch.data(), np);
  put(k.prof.mapped_count.data(), np * sizeof(std::uint16_t));
  put(k.prof.visible_count.data(), np * sizeof(std::uint16_t));
  pack_block_targets(k.targets, out);
}

RayBlock unpack_ray_block(const char* p, std::size_t n) {
  const char* const end = p + n;
  const auto get = [&](void* to, std::size_t bytes) {
    RIS_CHECK(std::size_t(end - p) >= bytes);
    std::memcpy(to, p, bytes);
    p += bytes;
  };
  RayBlock k;
  int head[5] = {};
  get(head, sizeof(head));
  k.k0 = head[0];
  k.k1 = head[1];
  k.prof.allocate(head[3], head[4], head[2]);
  get(&k.counts, sizeof(RayCounts));
  const std::size_t np = k.prof.power_w.size();
  get(k.prof.power_w.data(), np * sizeof(float));
  get(k.prof.area_m2.data(), np * sizeof(float));
  get(k.prof.touch.data(), np);
  get(k.prof.mapped_count.data(), np * sizeof(std::uint16_t));
  get(k.prof.visible_count.data(), np * sizeof(std::uint16_t));
  k.targets = unpack_block_targets(p, end);
  RIS_CHECK(p == end);
  return k;
}

PpiRayBlocks::PpiRayBlocks(const SceneStreamReader& in, const PpiGeometry& pg,
                           const RadiometrySetup& rs, const std::string& radar_file, int bins,
                           const PpiRayLayout& layout,
                           const std::vector<PointCandidate>& candidates,
                           std::vector<RayBlock>& spare)
    : in_(in),
      pg_(pg),
      rs_(rs),
      bins_(bins),
      layout_(layout),
      candidates_(candidates),
      spare_(spare),
      gain2_(rs.imaging.elevation_gain, rs.imaging.peak_gain, radar_file),
      ctx_(element_context(rs.imaging, gain2_, rs.lut, bins)) {}

int PpiRayBlocks::blocks() const {
  return (all_rays() + layout_.block_rays - 1) / layout_.block_rays;
}

// Block b's rays on this rank: their terrain from windows of the scene
// file, geometry and range profiles.
RayBlock PpiRayBlocks::compute(int b) {
  RayBlock k;
  if (!spare_.empty()) {  // buffers reused
    k = std::move(spare_.back());
    spare_.pop_back();
  }
  if (b == layout_.fail_block) {
    throw std::runtime_error(fmt::format("block {}: a failure injected by RIS_FAIL_BLOCK", b));
  }
  k.k0 = b * layout_.block_rays;
  k.k1 = std::min(all_rays(), k.k0 + layout_.block_rays);
  k.counts = RayCounts();
  block_counts_ = &k.counts;
  sample_block_terrain(k.k0, k.k1);
  std::optional<LinePointTargets> on_rays = candidates_on_rays(k.k0, k.k1);
  block_profiles(k.k0, k.k1, k.prof, k.counts, on_rays ? &*on_rays : nullptr);
  block_counts_ = nullptr;
  // Each candidate's result (by_line[i].target: the candidate's index).
  k.targets = BlockTargets();
  if (on_rays) {
    for (std::size_t i = 0; i < on_rays->by_line.size(); ++i) {
      k.targets.candidate.push_back(static_cast<std::int32_t>(on_rays->by_line[i].target));
      k.targets.lit.push_back(on_rays->lit[i]);
      k.targets.power_w.push_back(on_rays->power_w[i]);
    }
  }
  return k;
}

// The candidates on rays [k0, k1) for a block (none: nullopt).
std::optional<LinePointTargets> PpiRayBlocks::candidates_on_rays(int k0, int k1) const {
  std::vector<PointCandidate> on;
  for (const PointCandidate& c : candidates_)
    if (c.ret.line >= k0 && c.ret.line < k1) on.push_back(c);
  if (on.empty()) return std::nullopt;
  return LinePointTargets(std::move(on));
}

// The terrain of rays [k0, k1) (padded ray numbers), sampled into
// terrain_* (ray k - k0 at row (k - k0) x samples, sample j at j - begin).
void PpiRayBlocks::sample_block_terrain(int k0, int k1) {
  const int n = k1 - k0, samples = pg().rays.samples;
  const std::size_t cap = sz(n) * sz(samples);
  t_height_.resize(cap);
  t_dzdx_.resize(cap);
  t_dzdy_.resize(cap);
  t_cat_.resize(cap);
  t_flags_.resize(cap);
  lines_.resize(sz(n));
  span_.resize(sz(n));
  for (int k = k0; k < k1; ++k) {
    lines_[sz(k - k0)] = ppi_ray_line(grid(), pg(), k);
    span_[sz(k - k0)] = inside_samples(lines_[sz(k - k0)], grid().rows, grid().cols, samples);
  }
  // Range segment by segment; within one, groups of consecutive rays whose
  // cells fit a window.
  for (int a = 0; a < samples; a += layout_.segment_samples) {
    const int b = std::min(samples, a + layout_.segment_samples);
    CellBox group;
    int g0 = -1;
    for (int k = 0; k < n; ++k) {
      const CellBox box = ray_cells(k, a, b);
      if (box.empty()) continue;
      const CellBox u = group.united(box);
      if (g0 >= 0 && padded_cells(u) > layout_.window_cells) {
        sample_group(g0, k, a, b, group);
        group = box;
        g0 = k;
      } else {
        if (g0 < 0) g0 = k;
        group = u;
      }
    }
    if (g0 >= 0) sample_group(g0, n, a, b, group);
  }
}

// The cells ray k - k0's samples [a, b) touch (positions are monotone
// along a ray: its first and last sample bound them).
CellBox PpiRayBlocks::ray_cells(int k, int a, int b) const {
  const auto [begin, end] = span_[sz(k)];
  const int js = std::max(a, begin), je = std::min(b, end);
  if (js >= je) return {};
  return sample_cells(grid(), lines_[sz(k)], js)
      .united(sample_cells(grid(), lines_[sz(k)], je - 1));
}

// Rays [g0, g1) (block-relative), samples [a, b), from one window.
void PpiRayBlocks::sample_group(int g0, int g1, int a, int b, const CellBox& cells) {
  const TexelWindow tw = read_texel_window(in_, cells, ws_);
  const std::size_t nc = sz(tw.rows) * sz(tw.cols);
  ++block_counts_->windows;
  block_counts_->max_window_cells = std::max(block_counts_->max_window_cells, std::int64_t(nc));
  const int samples = pg().rays.samples;
#pragma omp parallel for schedule(dynamic, 1)
  for (int k = g0; k < g1; ++k) {
    const auto [begin, end] = span_[sz(k)];
    const int js = std::max(a, begin), je = std::min(b, end);
    if (js >= je) continue;
    const std::size_t at = sz(k) * sz(samples) + sz(js - begin);
    sample_from_window(tw, grid(), lines_[sz(k)], js, je,
                       {t_height_.data() + at, t_dzdx_.data() + at, t_dzdy_.data() + at,
                        t_cat_.data() + at, t_flags_.data() + at});
  }
}

// Rays [k0, k1) through the line engine: the windowed polar source's
// geometry from the sampled terrain, then each ray's range profile and
// point returns (the in-memory run's per-line stages,
// sim/sources/polar_lines.h), a ray per engine block as the threads take
// them.
void PpiRayBlocks::block_profiles(int k0, int k1, SlarLineProfiles& prof, RayCounts& counts,
                                  LinePointTargets* targets) {
  prof.allocate(k1 - k0, bins(), k0);
  prof.samples_in_swath = 0;
  const LineKeep keep{nullptr, nullptr, targets};
  const LineStages stages{ctx_, LineLookFrame{}, false, rs_.imaging.range_window_bins,
                          targets != nullptr ? &keep : nullptr};
  const SampledRays rays{
      pg(),           k0, span_, t_height_.data(), t_dzdx_.data(), t_dzdy_.data(), t_cat_.data(),
      t_flags_.data()};
  SlarLineCounts c;
  run_line_blocks(pg().rays, stages, k0, k1, 1, prof, c,
                  [&](LineScratch&) { return WindowedPolarThreadSource{rays}; });
  counts.in_swath += prof.samples_in_swath;
  counts.shadow += c.shadow;
  counts.layover += c.layover;
  counts.back_facing += c.back_facing;
  counts.nodata += c.nodata;
  counts.r_min = std::min(counts.r_min, c.r_min_m);
  counts.r_max = std::max(counts.r_max, c.r_max_m);
}

}  // namespace ris::detail
