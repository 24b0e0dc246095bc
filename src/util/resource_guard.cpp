#include "ris/util/resource_guard.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <thread>

#include "ris/util/error.h"
#include "ris/util/path_exists.h"

namespace ris {

namespace fs = std::filesystem;

namespace {

constexpr const char* kNoLimitsEnv = "RIS_NO_RESOURCE_LIMITS";
constexpr const char* kMaxThreadsEnv = "RIS_MAX_THREADS";
constexpr const char* kMaxMemoryEnv = "RIS_MAX_MEMORY_MB";
constexpr const char* kMaxDiskEnv = "RIS_MAX_DISK_MB";

// A ceiling in MiB from the environment, in bytes; -1 when unset.
std::int64_t env_cap_bytes(const char* name) {
  const char* env = std::getenv(name);
  if (env == nullptr || *env == '\0') return -1;
  char* end = nullptr;
  const long long mb = std::strtoll(env, &end, 10);
  if (end == env || *end != '\0' || mb < 1 || mb > (1LL << 40)) {
    throw InputError("", name, fmt::format("expected a whole number of MiB >= 1, got \"{}\"", env));
  }
  return mb * 1024 * 1024;
}

// What the machine has, lowered to the environment's ceiling when set.
std::int64_t capped(std::int64_t have, const char* env_name) {
  const std::int64_t cap = env_cap_bytes(env_name);
  return cap > 0 ? std::min(cap, have) : have;
}

int core_count() {
  const unsigned n = std::thread::hardware_concurrency();
  return n > 0 ? static_cast<int>(n) : 1;
}

// A refusal, or with the limits off a warning.
void refuse_or_warn(const std::string& file, const std::string& key, const std::string& message) {
  if (resource_limits_disabled()) {
    spdlog::warn("{}{}{}", file.empty() ? "" : file + ": ",
                 key.empty() ? "" : "'" + key + "': ", message);
    return;
  }
  throw InputError(file, key, message);
}

// Refuses (or, with the limits off, warns) when need > have.
void require(std::int64_t need, std::int64_t have, const std::string& file, const std::string& key,
             const std::string& what, const std::string& resource) {
  if (need <= have) return;
  const std::string message = fmt::format(
      "{} needs about {} of {}, but {} is available; use smaller inputs, or set {}=1 "
      "to run anyway",
      what, format_bytes(need), resource, format_bytes(have), kNoLimitsEnv);
  refuse_or_warn(file, key, message);
}

}  // namespace

std::int64_t checked_mul(std::int64_t a, std::int64_t b, const std::string& file,
                         const std::string& key) {
  std::int64_t out = 0;
  if (a < 0 || b < 0 || __builtin_mul_overflow(a, b, &out)) {
    throw InputError(file, key, fmt::format("{} x {} is out of range (a size overflow)", a, b));
  }
  return out;
}

std::int64_t checked_add(std::int64_t a, std::int64_t b, const std::string& file,
                         const std::string& key) {
  std::int64_t out = 0;
  if (a < 0 || b < 0 || __builtin_add_overflow(a, b, &out)) {
    throw InputError(file, key, fmt::format("{} + {} is out of range (a size overflow)", a, b));
  }
  return out;
}

std::int64_t checked_count(double value, std::int64_t max_count, const std::string& file,
                           const std::string& key, const std::string& what) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InputError(file, key, fmt::format("gives {} {} (expected a finite count)", value, what));
  }
  if (value > static_cast<double>(max_count)) {
    throw InputError(
        file, key,
        fmt::format("gives {:.4g} {}, more than the limit of {}", value, what, max_count));
  }
  return static_cast<std::int64_t>(value);
}

int max_threads() {
  const char* env = std::getenv(kMaxThreadsEnv);
  if (env != nullptr && *env != '\0') {
    char* end = nullptr;
    const long v = std::strtol(env, &end, 10);
    if (end == env || *end != '\0' || v < 1 || v > 1000000) {
      throw InputError("", kMaxThreadsEnv,
                       fmt::format("expected a whole number of threads >= 1, got \"{}\"", env));
    }
    return static_cast<int>(v);
  }
  return 4 * core_count();
}

int checked_thread_count(int requested, const std::string& key) {
  if (requested < 0) {
    throw InputError("", key, fmt::format("expected 0 (all cores) or more, got {}", requested));
  }
  if (requested == 0) return core_count();
  const int cap = max_threads();
  if (requested > cap) {
    throw InputError("", key,
                     fmt::format("{} threads is more than the limit of {} (4x the {} cores); set "
                                 "{}=N to allow more",
                                 requested, cap, core_count(), kMaxThreadsEnv));
  }
  return requested;
}

std::int64_t available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  std::string name, unit;
  std::int64_t kib = 0;
  while (meminfo >> name >> kib) {
    std::getline(meminfo, unit);
    if (name == "MemAvailable:") return kib * 1024;
  }
  const long pages = ::sysconf(_SC_AVPHYS_PAGES);
  const long page = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) return static_cast<std::int64_t>(pages) * page;
  return std::numeric_limits<std::int64_t>::max();  // unknown: do not refuse
}

std::int64_t free_disk_bytes(const fs::path& path) {
  fs::path p = fs::absolute(path);
  while (!p.empty() && !path_exists(p) && p != p.parent_path()) p = p.parent_path();
  std::error_code ec;
  const fs::space_info s = fs::space(p, ec);
  if (ec) return std::numeric_limits<std::int64_t>::max();  // unknown: do not refuse
  return static_cast<std::int64_t>(
      std::min<std::uintmax_t>(s.available, std::numeric_limits<std::int64_t>::max()));
}

bool resource_limits_disabled() {
  const char* env = std::getenv(kNoLimitsEnv);
  return env != nullptr && *env != '\0' && std::string(env) != "0";
}

void require_memory(std::int64_t bytes, const std::string& file, const std::string& key,
                    const std::string& what) {
  require(bytes, capped(available_memory_bytes(), kMaxMemoryEnv), file, key, what, "memory");
}

void require_disk(std::int64_t bytes, const fs::path& out, const std::string& file,
                  const std::string& key, const std::string& what) {
  require(bytes, capped(free_disk_bytes(out), kMaxDiskEnv), file, key, what,
          "disk at " + out.string());
}

void require_work(std::int64_t steps, std::int64_t max_steps, const std::string& file,
                  const std::string& key, const std::string& what) {
  if (steps <= max_steps) return;
  const std::string message = fmt::format(
      "{} come to {:.3g} steps, more than the {:.3g} ris allows a run of this size (it would "
      "run for minutes; docs/limits.md): use fewer or smaller objects, or set {}=1 to run "
      "anyway",
      what, static_cast<double>(steps), static_cast<double>(max_steps), kNoLimitsEnv);
  refuse_or_warn(file, key, message);
}

std::string format_bytes(std::int64_t bytes) {
  const double b = static_cast<double>(bytes);
  if (b >= 1024.0 * 1024 * 1024 * 1024) return fmt::format("{:.1f} TiB", b / std::pow(1024.0, 4));
  if (b >= 1024.0 * 1024 * 1024) return fmt::format("{:.1f} GiB", b / std::pow(1024.0, 3));
  if (b >= 1024.0 * 1024) return fmt::format("{:.1f} MiB", b / std::pow(1024.0, 2));
  return fmt::format("{} bytes", bytes);
}

}  // namespace ris
