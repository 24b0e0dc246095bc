#include "sim/stream/ppi_rays_pass.h"

#include <algorithm>
#include <limits>
#include <utility>

#include "ris/image/speckle.h"
#include "ris/util/error.h"
#include "sim/stream/slant_stream_passes.h"

namespace ris::detail {

namespace {

std::size_t sz(std::int64_t n) {
  return static_cast<std::size_t>(n);
}

}  // namespace

PpiRaysPass::PpiRaysPass(PpiRayBlocks& blocks, const PpiSimulation& sim, const RadiometrySetup& rs,
                         PpiRaySinks* sinks, RayTargetResults* targets,
                         const std::vector<double>& looks, std::uint64_t seed,
                         FloatRankSelect& power, ProgressBar& bar, std::int64_t cells,
                         std::vector<RayBlock>& spare)
    : blocks_(blocks),
      sim_(sim),
      rs_(rs),
      sinks_(sinks),
      targets_(targets),
      looks_(looks),
      seed_(seed),
      power_(power),
      bar_(bar),
      cells_(cells),
      spare_(spare) {
  if (sinks_ != nullptr) {
    const PpiGeometry& pg = sim.geometry;
    az_.emplace(rs.imaging, pg.rays.line_spacing_m, pg.rays.lines, sim.derived.range_bins);
  }
}

void PpiRaysPass::consume(int, RayBlock& k) {
  counts_.add(k.counts);
  // The block's candidates found lit or not, and their powers.
  const BlockTargets& t = k.targets;
  for (std::size_t i = 0; i < t.candidate.size(); ++i) {
    const auto c = static_cast<std::size_t>(t.candidate[i]);
    RIS_CHECK(targets_ != nullptr && c < targets_->lit.size());
    targets_->lit[c] = t.lit[i];
    targets_->power_w[c] = t.power_w[i];
  }
  az_->push(k.prof, k.k1 - k.k0);
  emit_ready();
  ++consumed_;
  bar_.advance(cells_ * (k.k1 - k.k0) / std::max(sim_.geometry.rays.lines, 1));
  if (spare_.size() < 2) spare_.push_back(std::move(k));
}

void PpiRaysPass::emit_ready() {
  SlarAzimuthIntegrator& az = *az_;
  const int n = az.lines_ready();
  if (n == 0) return;
  const int k0 = az.lines_emitted();
  const int bins = sim_.derived.range_bins;
  const int pad = sim_.geometry.pad, scan_rays = sim_.geometry.scan_rays;
  const std::size_t np = sz(n) * sz(bins);
  SlarImage block;
  block.lines = n;
  block.bins = bins;
  block.range = rs_.imaging.range;
  block.mean_power_w.resize(np);
  block.area_m2.resize(np);
  block.mask.resize(np);
  az.emit(n, block.mean_power_w.data(), block.area_m2.data(), block.mask.data());
  apply_switch_corrections(block, rs_.terms);
  const int s0 = std::max(k0, pad), s1 = std::min(k0 + n, pad + scan_rays);
  if (s1 <= s0) return;
  const int m = s1 - s0;
  const std::size_t at = block.index(s0 - k0, 0), nm = sz(m) * sz(bins);
  mean_.assign(block.mean_power_w.begin() + static_cast<std::ptrdiff_t>(at),
               block.mean_power_w.begin() + static_cast<std::ptrdiff_t>(at + nm));
  mask_.assign(block.mask.begin() + static_cast<std::ptrdiff_t>(at),
               block.mask.begin() + static_cast<std::ptrdiff_t>(at + nm));
  for (std::size_t i = 0; i < nm; ++i) {
    if (valid_power(mean_[i], mask_[i])) power_.count(mean_[i]);
    if (mask_[i] & pixel_flag::kNoData) mean_[i] = std::numeric_limits<float>::quiet_NaN();
  }
  speckled_ = mean_;
  const RadarParams& r = sim_.radar;
  if (r.switches.fading) apply_fading(speckled_, m, bins, looks_, r.fading, seed_, s0 - pad);
  sinks_->mean->write(mean_.data(), m);
  sinks_->speckled->write(speckled_.data(), m);
  sinks_->mask->write(mask_.data(), m);
}

void PpiRaysPass::close() {
  RIS_CHECK(az_->lines_emitted() == sim_.geometry.rays.lines);
  sinks_->mean->close();
  sinks_->speckled->close();
  sinks_->mask->close();
}

}  // namespace ris::detail
