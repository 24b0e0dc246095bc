// A progress bar with rate and time remaining, for long runs.
//
// On a terminal: a bar on stderr redrawn in place (~10 times a second). When
// stderr is not a terminal (a script, a log): the same text as plain lines,
// one every 10 s and one at each stage change, so a log shows a long run is
// alive. quiet: nothing at all. Thread-safe: any thread may call advance()
// (the count is atomic; redraws are throttled and done by whichever thread
// crosses the interval).
//
//   ris simulate: [##########..........]  52%  1.3 G cells  410 M cells/s  ETA 3 s
//
// Example:
//   ris::ProgressBar bar("simulate", total_cells, "cells", quiet);
//   for (...) { work(block); bar.advance(block_cells); }
//   bar.finish();
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <mutex>
#include <string>

namespace ris {

class ProgressBar {
 public:
  // total: units of work (> 0); unit: their name in the rate ("cells").
  // quiet: never draw.
  ProgressBar(std::string label, std::int64_t total, std::string unit, bool quiet = false);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  bool enabled() const { return enabled_; }
  // Adds n units done; redraws at most every 100 ms.
  void advance(std::int64_t n);
  // Sets a stage name shown after the bar (e.g. "writing products").
  void set_stage(const std::string& stage);
  // Clears the line (once); called by the destructor too.
  void finish();

  // The bar's text for `done` of `total` after `elapsed_s` (for tests).
  static std::string format_line(const std::string& label, std::int64_t done, std::int64_t total,
                                 const std::string& unit, double elapsed_s,
                                 const std::string& stage, int width);

 private:
  void draw(bool force);

  std::string label_, unit_, stage_;
  std::int64_t total_;
  bool enabled_;
  bool terminal_;  // a bar in place; else plain log lines
  bool finished_ = false;
  std::atomic<std::int64_t> done_{0};
  std::atomic<std::int64_t> next_draw_ns_{0};
  std::chrono::steady_clock::time_point start_;
  std::mutex draw_mutex_;
};

// Whether stderr is a terminal (progress output makes sense there).
bool stderr_is_terminal();

}  // namespace ris
