// The products folders `ris serve` keeps under --out (one "products-run<N>"
// per POST /api/products of a new run), bounded in number and bytes so that
// no client, however many runs it asks for, fills the disk: once a write
// goes over either bound the oldest folders (by modification time) are
// removed, the one just written never.
//
// Example:
//   std::vector<std::string> gone =
//       ris::prune_product_folders(out, out / "products-run7", {.max_folders = 20});
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace ris {

struct ProductFolderCap {
  std::size_t max_folders = 20;
  std::uintmax_t max_bytes = std::uintmax_t{1} << 30;  // 1 GiB
};

// "products-run" followed by digits.
bool is_product_folder_name(const std::string& name);

// Removes the oldest product folders in `out_dir` (never `keep`) until at
// most cap.max_folders remain and their files total at most cap.max_bytes
// (or only `keep` is left). Returns the names removed, oldest first.
std::vector<std::string> prune_product_folders(const std::filesystem::path& out_dir,
                                               const std::filesystem::path& keep,
                                               const ProductFolderCap& cap);

}  // namespace ris
