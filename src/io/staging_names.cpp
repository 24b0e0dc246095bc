#include "ris/io/staging_names.h"

#include <signal.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <charconv>
#include <fstream>
#include <optional>
#include <string_view>

namespace ris {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kPartial = ".partial-";

// Field 22 of /proc/<pid>/stat (the process's start, in clock ticks after
// boot), or nothing when the process or the file is gone. The command name
// (field 2) may hold spaces and parentheses: the fields after it start
// behind the last ')'.
std::optional<unsigned long long> start_ticks(long pid) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(in, line)) return std::nullopt;
  std::size_t pos = line.rfind(')');
  if (pos == std::string::npos) return std::nullopt;
  ++pos;
  for (int field = 3; field <= 22; ++field) {
    while (pos < line.size() && line[pos] == ' ') ++pos;
    const std::size_t end = line.find(' ', pos);
    if (field == 22) {
      unsigned long long v = 0;
      const auto r =
          std::from_chars(line.data() + pos, line.data() + std::min(end, line.size()), v);
      if (r.ec != std::errc()) return std::nullopt;
      return v;
    }
    if (end == std::string::npos) return std::nullopt;
    pos = end;
  }
  return std::nullopt;
}

unsigned long long own_start_ticks() {
  static const unsigned long long ticks = start_ticks(::getpid()).value_or(0);
  return ticks;
}

// The owner named after ".partial-": pid, and the start time when given.
struct Owner {
  long pid = 0;
  std::optional<unsigned long long> start;
};

// "<pid>-<start>-<n>..." or the earlier "<pid>-<n>...": the leading groups of
// digits joined by '-'.
std::optional<Owner> parse_owner(std::string_view rest) {
  std::vector<unsigned long long> groups;
  std::size_t pos = 0;
  while (groups.size() < 3) {
    unsigned long long v = 0;
    const auto r = std::from_chars(rest.data() + pos, rest.data() + rest.size(), v);
    if (r.ec != std::errc() || r.ptr == rest.data() + pos) break;
    groups.push_back(v);
    pos = static_cast<std::size_t>(r.ptr - rest.data());
    if (pos >= rest.size() || rest[pos] != '-') break;
    ++pos;
  }
  if (groups.size() < 2 || groups[0] == 0 || groups[0] > 4194304) return std::nullopt;
  Owner o{static_cast<long>(groups[0]), std::nullopt};
  if (groups.size() == 3) o.start = groups[1];
  return o;
}

bool owner_alive(const Owner& o) {
  const bool exists = ::kill(static_cast<pid_t>(o.pid), 0) == 0 || errno == EPERM;
  if (!exists) return false;
  if (!o.start) return true;  // the earlier form: a live pid may be its owner
  const std::optional<unsigned long long> now = start_ticks(o.pid);
  return !now || *now == *o.start;  // another start: the pid was reused
}

}  // namespace

std::string staging_suffix() {
  static std::atomic<unsigned> counter{0};
  return std::string(kPartial) + std::to_string(::getpid()) + "-" +
         std::to_string(own_start_ticks()) + "-" + std::to_string(counter++);
}

std::vector<fs::path> remove_stale_staging(const fs::path& folder, const std::string& final_name) {
  std::vector<fs::path> removed;
  const std::string file_prefix = final_name + std::string(kPartial);
  const std::string folder_prefix = "." + file_prefix;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(folder.empty() ? "." : folder, ec)) {
    const std::string name = entry.path().filename().string();
    std::string_view rest;
    if (name.starts_with(folder_prefix)) {
      rest = std::string_view(name).substr(folder_prefix.size());
    } else if (name.starts_with(file_prefix)) {
      rest = std::string_view(name).substr(file_prefix.size());
    } else {
      continue;
    }
    const std::optional<Owner> owner = parse_owner(rest);
    if (!owner || owner_alive(*owner)) continue;
    std::error_code rm;
    fs::remove_all(entry.path(), rm);
    if (rm) continue;
    spdlog::warn("removed {}, left unfinished by an earlier run (process {}, no longer running)",
                 entry.path().string(), owner->pid);
    removed.push_back(entry.path());
  }
  return removed;
}

}  // namespace ris
