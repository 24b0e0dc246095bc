#include "ris/util/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace ris {

namespace {

// 1234567 -> "1.23 M", 12 -> "12 " (SI prefixes up to T; the unit follows:
// "1.23 Mcells", "12 cells").
std::string si(double v) {
  const char* prefixes[] = {" ", " k", " M", " G", " T"};
  int p = 0;
  while (std::abs(v) >= 1000.0 && p < 4) {
    v /= 1000.0;
    ++p;
  }
  return fmt::format("{:.3g}{}", v, prefixes[p]);
}

std::string duration(double s) {
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 60) return fmt::format("{:.0f} s", s);
  if (s < 3600) return fmt::format("{}:{:02d}", int(s) / 60, int(s) % 60);
  return fmt::format("{}:{:02d}:{:02d}", int(s) / 3600, (int(s) / 60) % 60, int(s) % 60);
}

}  // namespace

bool stderr_is_terminal() {
  return isatty(STDERR_FILENO) != 0;
}

ProgressBar::ProgressBar(std::string label, std::int64_t total, std::string unit, bool quiet)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(std::max<std::int64_t>(total, 1)),
      enabled_(!quiet),
      terminal_(stderr_is_terminal()),
      start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  finish();
}

std::string ProgressBar::format_line(const std::string& label, std::int64_t done,
                                     std::int64_t total, const std::string& unit, double elapsed_s,
                                     const std::string& stage, int width) {
  const double f = std::clamp(double(done) / double(std::max<std::int64_t>(total, 1)), 0.0, 1.0);
  const int filled = static_cast<int>(std::lround(f * width));
  std::string bar(static_cast<std::size_t>(filled), '#');
  bar.append(static_cast<std::size_t>(width - filled), '.');
  const double rate = elapsed_s > 0 ? double(done) / elapsed_s : 0.0;
  const double eta = rate > 0 ? double(total - done) / rate : -1.0;
  std::string line;
  if (unit == "%" || unit == " %") {
    // Work counted in percent of a run (its stages' shares): the count is
    // the percentage and a rate of "%/s" says nothing, so the time taken
    // and the time left instead.
    line = fmt::format("ris {}: [{}] {:3.0f}%  {} elapsed  ETA {}", label, bar, 100.0 * f,
                       duration(elapsed_s), duration(eta));
  } else {
    const std::string u = unit.starts_with(' ') ? unit.substr(1) : unit;
    line = fmt::format("ris {}: [{}] {:3.0f}%  {}{}  {}{}/s  ETA {}", label, bar, 100.0 * f,
                       si(double(done)), u, si(rate), u, duration(eta));
  }
  if (!stage.empty()) line += "  " + stage;
  return line;
}

void ProgressBar::advance(std::int64_t n) {
  done_.fetch_add(n, std::memory_order_relaxed);
  if (enabled_) draw(false);
}

void ProgressBar::set_stage(const std::string& stage) {
  if (!enabled_) return;
  {
    std::lock_guard<std::mutex> lock(draw_mutex_);
    stage_ = stage;
  }
  draw(true);
}

void ProgressBar::draw(bool force) {
  const auto now = std::chrono::steady_clock::now();
  const std::int64_t now_ns =
      std::chrono::duration_cast<std::chrono::nanoseconds>(now - start_).count();
  std::int64_t next = next_draw_ns_.load(std::memory_order_relaxed);
  // A bar redrawn in place on a terminal; a plain line every 10 s in a log.
  const std::int64_t interval_ns = terminal_ ? 100'000'000 : 10'000'000'000;
  if (!force &&
      (now_ns < next || !next_draw_ns_.compare_exchange_strong(next, now_ns + interval_ns)))
    return;
  std::unique_lock<std::mutex> lock(draw_mutex_, std::try_to_lock);
  if (!lock.owns_lock() || finished_) return;
  const double elapsed = 1e-9 * double(now_ns);
  const std::string line = format_line(label_, done_.load(std::memory_order_relaxed), total_, unit_,
                                       elapsed, stage_, 24);
  if (terminal_) {
    fmt::print(stderr, "\r{:<100}", line);
  } else {
    fmt::print(stderr, "{}\n", line);
  }
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (!enabled_) return;
  std::lock_guard<std::mutex> lock(draw_mutex_);
  if (finished_) return;
  finished_ = true;
  if (!terminal_) return;  // log lines stay
  fmt::print(stderr, "\r{:<100}\r", "");
  std::fflush(stderr);
}

}  // namespace ris
