// The names of unfinished outputs, and who owns them.
//
// A file ris is writing goes to `<name>.partial-<pid>-<start>-<n><ext>`
// beside its final name, a folder to `.<name>.partial-<pid>-<start>-<n>`
// (ris/io/atomic_file.h): the owner's process id, the owner's start time
// (clock ticks after boot, /proc/<pid>/stat field 22: a pid alone may have
// been reused by the time someone looks) and a counter. A run that was
// killed (SIGKILL, a power cut) leaves such names behind; the next run
// writing the same output removes those whose owner is gone, and says so.
// Names of the earlier form `.partial-<pid>-<n>` count as stale when no
// process has that id.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ris {

// ".partial-<pid>-<start>-<n>", unique to this process and call.
std::string staging_suffix();

// Removes, in `folder`, the unfinished outputs for the final name
// `final_name` (as a file or a folder) whose owner process is gone; warns
// for each. Returns what it removed.
std::vector<std::filesystem::path> remove_stale_staging(const std::filesystem::path& folder,
                                                        const std::string& final_name);

}  // namespace ris
