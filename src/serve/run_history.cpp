#include "ris/serve/run_history.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ris/sensor/polarisation.h"
#include "ris/util/error.h"

namespace ris {
namespace {

// Equal to a part in 10^9 (the same radar gives the same doubles; a
// re-parsed one may differ in the last bits).
bool same(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max({1.0, std::abs(a), std::abs(b)});
}

std::string label_of(std::uint64_t id, const RunResult& run) {
  const RadarParams& r = run.radar;
  return fmt::format("run {}: {} {:.3f} GHz {}, seed {}", id, run_kind_name(run),
                     r.frequency_hz * 1e-9, to_string(r.polarisation), run.info.seed);
}

}  // namespace

std::string grid_difference(const SlantGrid& a, const SlantGrid& b) {
  if (a.lines != b.lines) return fmt::format("lines {} against {}", a.lines, b.lines);
  if (a.bins != b.bins) return fmt::format("bins {} against {}", a.bins, b.bins);
  if (!same(a.near_range_m, b.near_range_m)) {
    return fmt::format("near range {:.3f} m against {:.3f} m", a.near_range_m, b.near_range_m);
  }
  if (!same(a.range_bin_m, b.range_bin_m)) {
    return fmt::format("range bin {:.4f} m against {:.4f} m", a.range_bin_m, b.range_bin_m);
  }
  if (!same(a.line_spacing_m, b.line_spacing_m)) {
    return fmt::format("line spacing {:.4f} m against {:.4f} m", a.line_spacing_m,
                       b.line_spacing_m);
  }
  const Track& s = a.track;
  const Track& t = b.track;
  if (!same(s.start_x_m, t.start_x_m) || !same(s.start_y_m, t.start_y_m) ||
      !same(s.along_x, t.along_x) || !same(s.along_y, t.along_y) || !same(s.cross_x, t.cross_x) ||
      !same(s.cross_y, t.cross_y)) {
    return "another track over the scene (start, heading or look side)";
  }
  if (!same(s.altitude_m, t.altitude_m)) {
    return fmt::format("altitude {:.2f} m against {:.2f} m", s.altitude_m, t.altitude_m);
  }
  return "";
}

void check_same_grid(const KeptRun& current, const KeptRun& earlier) {
  const std::string why = grid_difference(current.grid, earlier.grid);
  if (why.empty()) return;
  throw InputError("request", "earlier",
                   fmt::format("run {} and run {} are not on the same grid ({}): only runs on "
                               "the same slant grid can be compared (change the band, "
                               "polarisation, film, seed or scene, not the geometry)",
                               current.id, earlier.id, why));
}

void RunHistory::keep(std::uint64_t id, const RunResult& run) {
  const SlarRun* slar = run.in_memory() ? slar_image_run(run) : nullptr;
  if (slar == nullptr) return;
  const SlarImage& img = slar->sim.image;
  KeptRun k;
  k.id = id;
  k.label = label_of(id, run);
  k.grid = {img.lines,       img.bins,           img.range.near_m,
            img.range.bin_m, img.line_spacing_m, slar->sim.track};
  k.mean_power_w.assign(img.mean_power_w.begin(), img.mean_power_w.end());
  k.speckled_power_w.assign(slar->pictures.speckled_power_w.begin(),
                            slar->pictures.speckled_power_w.end());
  k.grey.assign(slar->pictures.slant_grey.begin(), slar->pictures.slant_grey.end());
  runs_.push_back(std::move(k));
  std::size_t total = 0;
  for (const KeptRun& r : runs_) total += r.bytes();
  while (runs_.size() > 1 && (runs_.size() > max_runs_ || total > max_bytes_)) {
    total -= runs_.front().bytes();
    runs_.pop_front();
  }
}

const KeptRun& RunHistory::get(std::uint64_t id) const {
  std::string kept;
  for (const KeptRun& r : runs_) {
    if (r.id == id) return r;
    kept += (kept.empty() ? "" : ", ") + std::to_string(r.id);
  }
  throw InputError("request", "earlier",
                   fmt::format("run {} is not kept (the server keeps the last {} SLAR and SAR "
                               "runs; kept: {})",
                               id, max_runs_, kept.empty() ? "none" : kept));
}

nlohmann::json RunHistory::list(std::uint64_t current) const {
  const KeptRun* now = nullptr;
  for (const KeptRun& r : runs_) {
    if (r.id == current) now = &r;
  }
  nlohmann::json runs = nlohmann::json::array();
  for (const KeptRun& r : runs_) {
    nlohmann::json j = {
        {"id", r.id}, {"label", r.label}, {"lines", r.grid.lines}, {"bins", r.grid.bins}};
    const std::string why =
        now == nullptr ? "the current run is not kept (PPI)" : grid_difference(now->grid, r.grid);
    j["comparable"] = why.empty();
    if (!why.empty()) j["why_not"] = why;
    runs.push_back(std::move(j));
  }
  return {{"current", current}, {"runs", runs}};
}

}  // namespace ris
