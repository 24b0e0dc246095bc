// Outputs that are either complete or absent.
//
// Every file ris writes goes to a temporary name in the destination folder and
// is renamed into place only when complete, so a failure (bad input found
// late, a full disk, Ctrl-C) never leaves a half-written product. The
// temporary names carry their owner (ris/io/staging_names.h): one left by a
// killed run is removed by the next run writing the same output.
//
// Example:
//   ris::AtomicPath out("scene.tif");
//   write_something(out.temp_path());
//   out.commit();  // rename; without it the destructor deletes the temporary
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ris {

class AtomicPath {
 public:
  explicit AtomicPath(std::filesystem::path final_path);
  ~AtomicPath();
  AtomicPath(const AtomicPath&) = delete;
  AtomicPath& operator=(const AtomicPath&) = delete;

  // Where to write: same folder as the final path (so rename is atomic),
  // same extension (so format drivers that look at it are happy).
  const std::filesystem::path& temp_path() const { return temp_; }
  const std::filesystem::path& final_path() const { return final_; }
  void commit();

 private:
  std::filesystem::path final_;
  std::filesystem::path temp_;
  bool committed_ = false;
};

// Writes text to a file atomically.
void write_text_file_atomic(const std::filesystem::path& path, const std::string& text);

// An output folder filled as a whole: files are written into a hidden staging
// folder beside it; commit() moves them into the final folder (created if
// needed). Without commit() the staging folder is removed and the final folder
// is untouched.
class StagedDirectory {
 public:
  explicit StagedDirectory(std::filesystem::path final_dir);
  ~StagedDirectory();
  StagedDirectory(const StagedDirectory&) = delete;
  StagedDirectory& operator=(const StagedDirectory&) = delete;

  // Path at which to write the product `name` during staging.
  std::filesystem::path path(const std::string& name) const { return staging_ / name; }
  const std::filesystem::path& final_dir() const { return final_; }
  void commit();

 private:
  void forget_staging() noexcept;

  std::filesystem::path final_;
  std::filesystem::path staging_;
  bool committed_ = false;
};

// Removes the staging folder of every StagedDirectory, and the temporary
// file of every AtomicPath, alive in this process (from a thread that is
// ending the process on a signal, while another may still write into them:
// ris/io/interrupt_cleanup.h, an MPI rank stopped by mpirun, docs/scale.md).
// Returns the paths that existed and were removed.
std::vector<std::filesystem::path> remove_staged_directories() noexcept;

}  // namespace ris
