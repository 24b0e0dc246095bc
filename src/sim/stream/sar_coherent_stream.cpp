#include "sim/stream/sar_coherent_stream.h"

#include <algorithm>
#include <cstring>
#include <tuple>

#include "ris/util/error.h"

namespace ris::detail {

void pack_coherent_block(const CoherentBlock& b, std::vector<char>& out) {
  const std::size_t n = b.intensity.size();
  const char* c = reinterpret_cast<const char*>(&n);
  out.insert(out.end(), c, c + sizeof(n));
  c = reinterpret_cast<const char*>(b.intensity.data());
  out.insert(out.end(), c, c + n * sizeof(double));
}

CoherentBlock unpack_coherent_block(const char*& p, const char* end) {
  CoherentBlock b;
  std::size_t n = 0;
  RIS_CHECK(std::size_t(end - p) >= sizeof(n));
  std::memcpy(&n, p, sizeof(n));
  p += sizeof(n);
  RIS_CHECK(std::size_t(end - p) / sizeof(double) >= n);
  b.intensity.resize(n);
  std::memcpy(b.intensity.data(), p, n * sizeof(double));
  p += n * sizeof(double);
  return b;
}

CoherentStream::CoherentStream(const SlarSimulation& sim, std::uint64_t seed)
    : sim_(sim),
      seed_(seed),
      h_(SincTable::shared(), sim.image, sim.radar),
      terms_(switched_terms(sim.radar)),
      lines_(sim.image.lines),
      bins_(sim.image.bins),
      samples_(sim.geometry.samples),
      looks_(sim.radar.sar.range_looks * sim.radar.sar.azimuth_looks) {
  RIS_CHECK(sim.radar.mode == RadarMode::sar && sim.radar.sar.coherent);
}

std::pair<int, int> CoherentStream::lines_read(int l0, int l1) const {
  return {std::max(0, l0 - halo_lines()), std::min(lines_, l1 + halo_lines())};
}

void CoherentStream::run_block(const RunLines& run, int l0, int l1, const StreamTargets* targets,
                               SlarLineProfiles& prof, SlarLineCounts& counts, BlockTargets& bt,
                               CoherentBlock& out) {
  const auto [h0, h1] = lines_read(l0, l1);
  const std::size_t n_read = std::size_t(h1 - h0) * std::size_t(samples_);
  element_power_.assign(n_read, 0.0f);
  slant_range_.resize(n_read);
  std::optional<LinePointTargets> on_lines;
  if (targets) on_lines = targets->candidates_on_lines(h0, h1);
  LineKeep keep;
  keep.element_power_w = element_power_.data();
  keep.slant_range_m = slant_range_.data();
  keep.line0 = h0;
  keep.targets = on_lines ? &*on_lines : nullptr;
  // Every line read through the engine; the halo's counts, maps and
  // samples in the swath are the neighbouring blocks' (dropped here).
  read_prof_.allocate(h1 - h0, bins_, h0);
  SlarLineCounts halo_counts;
  if (h0 < l0) run(h0, l0, false, read_prof_, halo_counts, keep);
  read_prof_.samples_in_swath = 0;
  run(l0, l1, true, read_prof_, counts, keep);
  const std::int64_t own_in_swath = read_prof_.samples_in_swath;
  if (l1 < h1) run(l1, h1, false, read_prof_, halo_counts, keep);
  // Its own lines' profiles, for the azimuth integration on rank 0.
  prof.allocate(l1 - l0, bins_, l0);
  prof.samples_in_swath = own_in_swath;
  const std::size_t at = read_prof_.index(l0, 0), n = prof.power_w.size();
  std::copy_n(read_prof_.power_w.begin() + std::ptrdiff_t(at), n, prof.power_w.begin());
  std::copy_n(read_prof_.area_m2.begin() + std::ptrdiff_t(at), n, prof.area_m2.begin());
  std::copy_n(read_prof_.touch.begin() + std::ptrdiff_t(at), n, prof.touch.begin());
  std::copy_n(read_prof_.mapped_count.begin() + std::ptrdiff_t(at), n, prof.mapped_count.begin());
  std::copy_n(read_prof_.visible_count.begin() + std::ptrdiff_t(at), n, prof.visible_count.begin());
  // Its own lines' targets for rank 0 (each target reported by one block).
  bt = BlockTargets{};
  if (on_lines) {
    const BlockTargets all = targets->block_result(*on_lines);
    for (std::size_t k = 0; k < all.candidate.size(); ++k) {
      const int line = targets->candidates()[std::size_t(all.candidate[k])].ret.line;
      if (line < l0 || line >= l1) continue;
      bt.candidate.push_back(all.candidate[k]);
      bt.lit.push_back(all.lit[k]);
      bt.power_w.push_back(all.power_w[k]);
    }
  }
  compress(l0, l1, h0, h1, on_lines ? &*on_lines : nullptr, out);
}

void CoherentStream::compress(int l0, int l1, int h0, int h1, const LinePointTargets* on_lines,
                              CoherentBlock& out) {
  const std::size_t bins = std::size_t(bins_), samples = std::size_t(samples_);
  const std::size_t n_own = std::size_t(l1 - l0) * bins;
  range_lines_.resize(std::size_t(h1 - h0) * bins);
  z_.resize(n_own);
  out.intensity.assign(n_own, 0.0);
  // The lit targets among the lines read, in target order (the order the
  // in-memory run adds them in: its point_returns).
  std::vector<std::tuple<std::size_t, std::size_t, double>> lit;  // target, k, power
  if (on_lines) {
    for (std::size_t k = 0; k < on_lines->by_line.size(); ++k)
      if (on_lines->lit[k]) lit.emplace_back(on_lines->by_line[k].target, k, on_lines->power_w[k]);
    std::sort(lit.begin(), lit.end());
  }
  for (int look = 0; look < looks_; ++look) {
    const auto phase_stream = kCoherentPhaseStream + static_cast<std::uint32_t>(look);
    const auto noise_stream = kCoherentNoiseStream + static_cast<std::uint32_t>(look);
#pragma omp parallel for schedule(dynamic, 8)
    for (int line = h0; line < h1; ++line) {
      const std::size_t r = std::size_t(line - h0);
      range_compress_line(h_, line, samples_, element_power_.data() + r * samples,
                          slant_range_.data() + r * samples, bins_, seed_, phase_stream,
                          range_lines_.data() + r * bins);
    }
#pragma omp parallel for schedule(static)
    for (int k = l0; k < l1; ++k) {
      azimuth_compress_line(h_, k, lines_, bins_, range_lines_.data(), h0, sim_.noise_power_w,
                            seed_, noise_stream, z_.data() + std::size_t(k - l0) * bins);
    }
    for (const auto& [target, k, power] : lit) {
      add_point_target(h_, on_lines->by_line[k].ret, power, lines_, bins_, l0, l1, z_.data(), l0);
    }
#pragma omp parallel for schedule(static)
    for (std::size_t i = 0; i < n_own; ++i) out.intensity[i] += double(std::norm(z_[i])) / looks_;
  }
}

void CoherentStream::add(CoherentBlock&& b) {
  // Drop what is finished before growing (the pending lines stay a few
  // blocks long).
  if (pending_at_ > 0) {
    pending_.erase(pending_.begin(), pending_.begin() + std::ptrdiff_t(pending_at_));
    pending_at_ = 0;
  }
  pending_.insert(pending_.end(), b.intensity.begin(), b.intensity.end());
}

void CoherentStream::finish_lines(int n, const std::uint8_t* mask, const float* area_m2,
                                  float* out) {
  const std::size_t bins = std::size_t(bins_);
  RIS_CHECK(pending_.size() - pending_at_ >= std::size_t(n) * bins);
  for (int l = 0; l < n; ++l) {
    const std::size_t at = std::size_t(l) * bins;
    finish_coherent_line(terms_, sim_.image.range, pending_.data() + pending_at_ + at, mask + at,
                         area_m2 + at, bins_, out + at);
  }
  pending_at_ += std::size_t(n) * bins;
}

}  // namespace ris::detail
