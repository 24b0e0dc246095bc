// Bounds on what one run may ask of the machine, checked before the work.
//
// Every size that comes from an input (image lines x samples, a scene's
// cells, an angle count, a thread count) goes through checked 64-bit
// arithmetic here, and the memory, disk and thread needs estimated from it
// are compared with what the machine has (MemAvailable of /proc/meminfo,
// std::filesystem::space at the output, 4x the cores) before any large
// allocation or long loop. A refusal is an InputError naming the key, the
// estimate and the limit, and how to raise the limit:
//   RIS_MAX_THREADS=N            allow up to N threads (default 4x cores)
//   RIS_MAX_MEMORY_MB=N          allow at most N MiB of memory, or
//   RIS_MAX_DISK_MB=N            of disk, below what is available (a
//                                shared machine; tests)
//   RIS_NO_RESOURCE_LIMITS=1     skip the memory, disk and work checks
//                                (warn instead; for a machine with swap or
//                                a disk that std::filesystem cannot see)
// (docs/limits.md).
//
// Example:
//   const std::int64_t n = checked_mul(lines, samples, "radar.toml", "azimuth_line_spacing");
//   require_memory(checked_mul(n, 40, ...), "radar.toml", "azimuth_line_spacing",
//                  "the image's geometry arrays");
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

namespace ris {

// a * b and a + b for non-negative counts; InputError (file, key) on
// overflow of int64 rather than a wrapped value.
std::int64_t checked_mul(std::int64_t a, std::int64_t b, const std::string& file,
                         const std::string& key);
std::int64_t checked_add(std::int64_t a, std::int64_t b, const std::string& file,
                         const std::string& key);

// A count computed in floating point (extent / step, ...) as an integer:
// InputError unless finite, >= 0 and <= max_count (what: the count's name).
std::int64_t checked_count(double value, std::int64_t max_count, const std::string& file,
                           const std::string& key, const std::string& what);

// The largest count of items any one loop or array of ris may have (2^31 - 1:
// indices are int in places, and 2 G items of anything is past any scene
// ris is meant for).
constexpr std::int64_t kMaxItems = 2147483647;

// Threads: 0 means all cores; otherwise 1..max_threads() or InputError
// naming `key`. Returns the count to use.
int checked_thread_count(int requested, const std::string& key);
// The thread cap: $RIS_MAX_THREADS when set, else 4x the cores.
int max_threads();

// Bytes of memory available to a new allocation (MemAvailable from
// /proc/meminfo; sysconf's free pages when it is absent).
std::int64_t available_memory_bytes();
// Bytes free for an unprivileged user on the file system holding `path`
// (or its nearest existing parent).
std::int64_t free_disk_bytes(const std::filesystem::path& path);

// Whether $RIS_NO_RESOURCE_LIMITS is set (checks warn instead of refusing).
bool resource_limits_disabled();

// InputError (file, key) when `bytes` exceed the available memory (or
// $RIS_MAX_MEMORY_MB when lower); what: what the memory is for. Warns
// instead when the limits are off.
void require_memory(std::int64_t bytes, const std::string& file, const std::string& key,
                    const std::string& what);
// InputError when `bytes` exceed the free disk at `out`.
void require_disk(std::int64_t bytes, const std::filesystem::path& out, const std::string& file,
                  const std::string& key, const std::string& what);

// InputError (file, key) when a loop would take more than `max_steps`
// steps (cell tests, ray samples): work that a small file can ask for and
// that would run for minutes. what: what the steps are ("the objects' cell
// tests"). Warns instead when the limits are off.
void require_work(std::int64_t steps, std::int64_t max_steps, const std::string& file,
                  const std::string& key, const std::string& what);

// Bytes as a short human figure ("1.5 GiB").
std::string format_bytes(std::int64_t bytes);

}  // namespace ris
