#include "ris/io/atomic_file.h"

#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <mutex>
#include <system_error>
#include <vector>

#include "ris/io/safe_paths.h"
#include "ris/io/staging_names.h"
#include "ris/util/error.h"
#include "ris/util/path_exists.h"

namespace ris {

namespace fs = std::filesystem;

namespace {
// The staging folders of the StagedDirectory objects, and the temporary
// files of the AtomicPath objects, alive in this process
// (remove_staged_directories).
std::mutex& staged_mutex() {
  static std::mutex m;
  return m;
}
std::vector<fs::path>& staged_folders() {
  static std::vector<fs::path> v;
  return v;
}

void remember(const fs::path& p) {
  const std::lock_guard<std::mutex> lock(staged_mutex());
  staged_folders().push_back(p);
}

void forget(const fs::path& p) noexcept {
  const std::lock_guard<std::mutex> lock(staged_mutex());
  std::vector<fs::path>& v = staged_folders();
  const auto it = std::find(v.begin(), v.end(), p);
  if (it != v.end()) v.erase(it);
}

// A file or folder and GDAL's side-car beside a file.
void remove_with_side_car(const fs::path& p) {
  std::error_code ec;
  fs::remove_all(p, ec);
  fs::path aux = p;
  aux += ".aux.xml";
  fs::remove(aux, ec);
}
}  // namespace

std::vector<fs::path> remove_staged_directories() noexcept {
  std::vector<fs::path> removed;
  const std::lock_guard<std::mutex> lock(staged_mutex());
  for (const fs::path& p : staged_folders()) {
    // The writing thread may still add a file between listing and removal:
    // a few tries.
    bool was_there = false;
    for (int attempt = 0; attempt < 20; ++attempt) {
      std::error_code ec;
      was_there = was_there || fs::exists(fs::symlink_status(p, ec));
      remove_with_side_car(p);
      if (!path_exists(p)) break;
    }
    if (was_there) {
      try {
        removed.push_back(p);
      } catch (...) {  // out of memory: removed all the same, just not listed
      }
    }
  }
  return removed;
}

AtomicPath::AtomicPath(fs::path final_path) : final_(std::move(final_path)) {
  fs::path parent = final_.parent_path();
  if (!parent.empty() && !fs::is_directory(parent)) {
    throw InputError(final_.string(), "",
                     "the output folder " + parent.string() + " does not exist");
  }
  require_safe_output_file(final_);  // no device, FIFO, folder or input
  remove_stale_staging(parent, final_.filename().string());
  temp_ = final_;
  temp_ += staging_suffix();
  temp_ += final_.extension();
  remember(temp_);
}

AtomicPath::~AtomicPath() {
  if (!committed_) remove_with_side_car(temp_);  // and GDAL's side-car
  forget(temp_);
}

void AtomicPath::commit() {
  require_safe_output_file(final_);  // again: inputs read since the start count too
  std::error_code ec;
  fs::rename(temp_, final_, ec);
  if (ec)
    throw InputError(final_.string(), "",
                     "cannot move the finished file into place: " + ec.message());
  fs::path aux = temp_;
  aux += ".aux.xml";
  fs::remove(aux, ec);
  committed_ = true;
  forget(temp_);
}

void write_text_file_atomic(const fs::path& path, const std::string& text) {
  AtomicPath out(path);
  {
    std::ofstream f(out.temp_path(), std::ios::binary);
    if (!f) throw InputError(path.string(), "", "cannot open for writing");
    f << text;
    f.flush();
    if (!f) throw InputError(path.string(), "", "write failed (disk full?)");
  }
  out.commit();
}

StagedDirectory::StagedDirectory(fs::path final_dir) : final_(std::move(final_dir)) {
  if (final_.empty()) final_ = ".";
  if (path_exists(final_) && !fs::is_directory(final_)) {
    throw InputError(final_.string(), "", "the output path exists and is not a folder");
  }
  fs::path parent = fs::absolute(final_).parent_path();
  if (!fs::is_directory(parent)) {
    throw InputError(final_.string(), "",
                     "the parent folder " + parent.string() + " does not exist");
  }
  require_outside_system_trees(final_);
  staging_ = fs::absolute(final_).lexically_normal();
  if (staging_.filename().empty()) staging_ = staging_.parent_path();
  remove_stale_staging(staging_.parent_path(), staging_.filename().string());
  staging_ = staging_.parent_path() / ("." + staging_.filename().string() + staging_suffix());
  remember(staging_);  // known before it exists (remove_staged_directories)
  try {
    fs::create_directories(staging_);
  } catch (...) {
    forget_staging();
    throw;
  }
}

void StagedDirectory::forget_staging() noexcept {
  forget(staging_);
}

StagedDirectory::~StagedDirectory() {
  std::error_code ec;
  fs::remove_all(staging_, ec);
  forget_staging();
}

void StagedDirectory::commit() {
  fs::create_directories(final_);
  std::vector<fs::path> names;
  for (const auto& entry : fs::directory_iterator(staging_)) {
    const fs::path name = entry.path().filename();
    if (name.string().size() > 8 && name.extension() == ".xml" &&
        name.string().find(".aux.xml") != std::string::npos) {
      continue;  // GDAL statistics side-cars are not products
    }
    names.push_back(name);
  }
  // Every destination checked before the first is moved: all or nothing.
  for (const fs::path& name : names) require_safe_output_file(final_ / name);
  for (const fs::path& name : names) {
    const fs::path staged = staging_ / name;
    std::error_code ec;
    fs::rename(staged, final_ / name, ec);
    if (ec) {
      throw InputError(final_.string(), "",
                       "cannot move " + name.string() + " into place: " + ec.message());
    }
  }
  committed_ = true;
}

}  // namespace ris
