// The runs `ris serve` keeps for comparing (docs/serve.md, "Comparing two
// runs"): each SLAR or SAR run's slant image (mean and speckled power,
// greytones) and the grid it lies on, the newest last, the oldest dropped
// beyond a count or a byte budget. PPI runs are not kept (a scope is not a
// slant grid).
//
// Two runs are compared only on the same grid: the same lines and bins, near
// range, bin and line spacing, and the same track over the scene (start,
// direction, altitude, look side), so pixel (line, bin) of one images the
// place it images in the other.
//
// Example:
//   ris::RunHistory h;
//   h.keep(3, result);
//   const ris::KeptRun& earlier = h.get(2);
//   ris::check_same_grid(h.get(3), earlier);
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/sim/run.h"

namespace ris {

// Where a slant image lies: its size and spacings and the track it was
// imaged from.
struct SlantGrid {
  int lines = 0;
  int bins = 0;
  double near_range_m = 0.0;
  double range_bin_m = 0.0;
  double line_spacing_m = 0.0;
  Track track;
};

struct KeptRun {
  std::uint64_t id = 0;
  std::string label;  // "run 3: sar 9.600 GHz VV, seed 1"
  SlantGrid grid;
  std::vector<float> mean_power_w;      // lines x bins
  std::vector<float> speckled_power_w;  // lines x bins
  std::vector<std::uint8_t> grey;       // lines x bins
  std::size_t bytes() const {
    return (mean_power_w.size() + speckled_power_w.size()) * sizeof(float) + grey.size();
  }
};

// Empty when a and b are on the same grid; else what differs ("bins 241
// against 300"), for the refusal.
std::string grid_difference(const SlantGrid& a, const SlantGrid& b);

// Throws InputError (source "request", key "earlier") unless the two runs
// are on the same grid, naming both runs and what differs.
void check_same_grid(const KeptRun& current, const KeptRun& earlier);

class RunHistory {
 public:
  explicit RunHistory(std::size_t max_runs = 8, std::size_t max_bytes = std::size_t{256} << 20)
      : max_runs_(max_runs), max_bytes_(max_bytes) {}

  // Keeps run `id`'s slant image (SLAR, SAR in memory; others ignored),
  // dropping the oldest beyond the caps (never the newest).
  void keep(std::uint64_t id, const RunResult& run);
  // Throws InputError naming the runs kept when `id` is not among them.
  const KeptRun& get(std::uint64_t id) const;
  // {"runs": [{"id", "label", "lines", "bins", "comparable", "why_not"}...]}
  // against run `current` (the newest when it is kept).
  nlohmann::json list(std::uint64_t current) const;

 private:
  std::size_t max_runs_;
  std::size_t max_bytes_;
  std::deque<KeptRun> runs_;
};

}  // namespace ris
