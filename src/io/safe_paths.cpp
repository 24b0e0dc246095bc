#include "ris/io/safe_paths.h"

#include <algorithm>
#include <mutex>

#include "ris/util/error.h"

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

}  // namespace

void require_regular_input(const std::string& path, const std::string& key) {
  std::error_code ec;
  const fs::file_status s = fs::status(path, ec);  // follows a symlink
  if (ec || !fs::exists(s)) throw InputError(path, key, "no such file");
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
  if (ec || link.type() == fs::file_type::not_found) return;  // a new path
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
