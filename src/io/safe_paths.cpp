#include "ris/io/safe_paths.h"

#include <algorithm>
#include <mutex>
#include <optional>

#include "ris/util/error.h"
#include "ris/util/spelling.h"

namespace ris {

namespace fs = std::filesystem;

namespace {

struct InputRecord {
  std::mutex mutex;
  bool on = false;
  std::vector<fs::path> paths;
};

InputRecord& record() {
  static InputRecord r;
  return r;
}

// "a FIFO", "a folder", ... for a message.
std::string kind_of(const fs::file_status& s) {
  switch (s.type()) {
    case fs::file_type::regular:
      return "a regular file";
    case fs::file_type::directory:
      return "a folder";
    case fs::file_type::fifo:
      return "a FIFO (named pipe)";
    case fs::file_type::socket:
      return "a socket";
    case fs::file_type::block:
    case fs::file_type::character:
      return "a device";
    default:
      return "not a regular file";
  }
}

// The kernel's file systems, where a "file" is a device, a process's
// descriptor or a kernel setting: /dev/stdout is a link to /proc/self/fd/1,
// and renaming a product over it (as root) would replace the system's link.
bool in_system_tree(const fs::path& p) {
  auto it = p.begin();
  if (it == p.end() || *it != "/") return false;
  ++it;
  if (it == p.end()) return false;
  if (*it == "proc" || *it == "sys") return true;
  if (*it != "dev") return false;
  ++it;
  return it == p.end() || *it != "shm";  // /dev/shm: a tmpfs for ordinary files
}

// " (did you mean \"x\"?)" for a file of the same folder one slip from the
// missing one's name, or where the folder is missing, a note saying so.
std::string nearby_names(const fs::path& path) {
  const fs::path folder = path.parent_path().empty() ? fs::path(".") : path.parent_path();
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return " (nor its folder " + folder.string() + ")";
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(folder, ec)) {
    if (names.size() >= 1000) break;  // a huge folder: no suggestion rather than a slow one
    names.push_back(e.path().filename().string());
  }
  const std::optional<std::string> near = nearest_name(path.filename().string(), names);
  return near ? " (did you mean " + (folder / *near).string() + "?)" : "";
}

}  // namespace

void require_outside_system_trees(const fs::path& path, const std::string& key) {
  std::error_code ec;
  const fs::path named = fs::absolute(path, ec).lexically_normal();
  fs::path resolved = fs::weakly_canonical(named.parent_path(), ec);
  if (!ec) resolved /= named.filename();
  fs::path target;
  if (fs::is_symlink(fs::symlink_status(path, ec))) {
    target = fs::read_symlink(path, ec);
    if (!ec && target.is_relative()) target = named.parent_path() / target;
    target = target.lexically_normal();
  }
  for (const fs::path& p : {named, resolved, target}) {
    if (in_system_tree(p)) {
      throw InputError(path.string(), key,
                       "lies in " + p.string() +
                           ", a device or kernel file system (/dev, /proc, /sys); ris writes "
                           "products only into ordinary folders: write to a file and copy it "
                           "where it must go");
    }
  }
}

void require_regular_input(const std::string& path, const std::string& key) {
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);  // follows a symlink
  if (ec || !fs::exists(s)) throw InputError(path, key, "no such file" + nearby_names(path));
  if (!fs::is_regular_file(s)) {
    throw InputError(path, key, "is " + kind_of(s) + "; expected a regular file");
  }
  InputRecord& r = record();
  std::lock_guard<std::mutex> lock(r.mutex);
  if (r.on) r.paths.push_back(fs::absolute(path).lexically_normal());
}

void require_safe_output_file(const fs::path& path, const std::string& key) {
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(path, ec);  // the link itself
  if (ec || link.type() == fs::file_type::not_found) {        // a new path
    require_outside_system_trees(path, key);
    return;
  }
  if (fs::is_symlink(link)) {
    const fs::file_status target = fs::status(path, ec);
    if (!ec && fs::exists(target) && !fs::is_regular_file(target)) {
      throw InputError(path.string(), key,
                       "is a link to " + kind_of(target) +
                           "; ris writes only new files or replaces regular files");
    }
  } else if (!fs::is_regular_file(link)) {
    throw InputError(
        path.string(), key,
        "is " + kind_of(link) + "; ris writes only new files or replaces regular files");
  }
  // A regular file or a link to one, but in /dev or /proc (/dev/stdout
  // redirected to a file): its name is the system's.
  require_outside_system_trees(path, key);
  for (const fs::path& input : tracked_inputs()) {
    if (fs::equivalent(path, input, ec) && !ec) {
      throw InputError(
          path.string(), key,
          "is also an input of this run (" + input.string() + "); write the output elsewhere");
    }
  }
}

void require_safe_output_folder(const fs::path& dir, const std::vector<std::string>& product_stems,
                                const std::string& key) {
  require_outside_system_trees(dir, key);
  std::error_code ec;
  const fs::file_status s = fs::status(dir, ec);
  if (ec || !fs::exists(s)) return;  // made by the run
  if (!fs::is_directory(s)) {
    throw InputError(dir.string(), key, "is " + kind_of(s) + "; expected a folder");
  }
  // A product's name already taken by a folder, FIFO or device, or by one
  // of the run's inputs: refused now rather than when the finished products
  // are moved in.
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string stem = entry.path().stem().string();
    if (std::find(product_stems.begin(), product_stems.end(), stem) != product_stems.end()) {
      require_safe_output_file(entry.path(), key);
    }
  }
}

void track_inputs(bool on) {
  InputRecord& r = record();
  std::lock_guard<std::mutex> lock(r.mutex);
  r.on = on;
}

std::vector<fs::path> tracked_inputs() {
  InputRecord& r = record();
  std::lock_guard<std::mutex> lock(r.mutex);
  return r.paths;
}

}  // namespace ris
