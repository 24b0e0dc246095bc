#include "ris/serve/product_folders.h"

#include <algorithm>
#include <cctype>
#include <tuple>

namespace ris {
namespace {

constexpr const char* kPrefix = "products-run";

struct Folder {
  std::filesystem::file_time_type modified;
  std::string name;
  std::uintmax_t bytes = 0;
};

// The files under `dir`, symbolic links not followed.
std::uintmax_t bytes_under(const std::filesystem::path& dir) {
  std::uintmax_t total = 0;
  std::error_code ec;
  for (auto it = std::filesystem::recursive_directory_iterator(dir, ec);
       !ec && it != std::filesystem::recursive_directory_iterator(); it.increment(ec)) {
    if (it->is_regular_file(ec) && !it->is_symlink(ec)) total += it->file_size(ec);
  }
  return total;
}

}  // namespace

bool is_product_folder_name(const std::string& name) {
  const std::string prefix = kPrefix;
  if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) return false;
  return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(prefix.size()), name.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}

std::vector<std::string> prune_product_folders(const std::filesystem::path& out_dir,
                                               const std::filesystem::path& keep,
                                               const ProductFolderCap& cap) {
  std::vector<Folder> folders;
  std::uintmax_t total = 0;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(out_dir, ec)) {
    const std::string name = e.path().filename().string();
    if (!is_product_folder_name(name) || e.is_symlink() || !e.is_directory()) continue;
    Folder f{e.last_write_time(ec), name, bytes_under(e.path())};
    total += f.bytes;
    folders.push_back(f);
  }
  std::sort(folders.begin(), folders.end(), [](const Folder& a, const Folder& b) {
    return std::tie(a.modified, a.name) < std::tie(b.modified, b.name);
  });
  const std::string kept = keep.filename().string();
  std::vector<std::string> removed;
  std::size_t count = folders.size();
  for (const Folder& f : folders) {
    if (count <= cap.max_folders && total <= cap.max_bytes) break;
    if (f.name == kept) continue;
    std::filesystem::remove_all(out_dir / f.name);
    removed.push_back(f.name);
    --count;
    total -= f.bytes;
  }
  return removed;
}

}  // namespace ris
