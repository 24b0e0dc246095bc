// What ris will read from and write to: regular files only, and never an
// input as an output.
//
// Inputs: every file is checked to be a regular file (or a symlink to one)
// before it is opened: a FIFO would block the reader (GDAL, the TOML parser)
// forever, a device or folder gives confusing errors.
//
// Outputs: never in /dev, /proc or /sys (as named or through a link); the
// final path must be new or a regular file (a device, FIFO,
// socket or folder is refused; as root, renaming over /dev/full would
// replace the device node) and must not resolve to a file this run read
// (std::filesystem::equivalent). A symlink at the output path is replaced
// itself (rename never writes through it), so a link never leads a write
// out of the output folder; a link to something that is not a regular file
// is refused.
//
// The command-line tool records every input it opens (track_inputs(true) in
// main: one process, one run); AtomicPath and StagedDirectory check their
// final paths against that record, so every writer is covered without being
// told its inputs. Library users (tests, the Python module) do not record.
//
// Example:
//   require_regular_input(path);           // before opening
//   require_safe_output_file("scene.tif"); // before the work
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ris {

// InputError (path, key) unless path names an existing regular file;
// records it when tracking is on.
void require_regular_input(const std::string& path, const std::string& key = "");

// InputError (path, key) when the output file may not be written: an
// existing non-regular file (or a link to one), or one of the recorded
// inputs.
void require_safe_output_file(const std::filesystem::path& path, const std::string& key = "");

// InputError (path, key) when an output path lies in /dev, /proc or /sys
// (/dev/shm excepted), as named, with its folder resolved, or as the target
// of a link at it: /dev/stdout is a link into /proc, and renaming a product
// over it would replace the system's link.
void require_outside_system_trees(const std::filesystem::path& path, const std::string& key = "");

// The same for an output folder: InputError when it exists and is not a
// folder, when it holds something other than a regular file under one of
// the names the run will write (stems: file names without extension), or
// when a recorded input lies directly in it under such a name.
void require_safe_output_folder(const std::filesystem::path& dir,
                                const std::vector<std::string>& product_stems,
                                const std::string& key = "");

// Turns the record of inputs on (the CLI) or off; off by default.
void track_inputs(bool on);
// The inputs recorded so far (absolute paths).
std::vector<std::filesystem::path> tracked_inputs();

}  // namespace ris
