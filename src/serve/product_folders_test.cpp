// The cap on the products folders the server keeps
// (ris/serve/product_folders.h): oldest first, the newest always kept, other
// files and folders never touched.
#include "ris/serve/product_folders.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

// products-run<i> with one file of `bytes`, modified i minutes after t0.
void make_folder(const fs::path& out, int i, std::size_t bytes) {
  const fs::path dir = out / ("products-run" + std::to_string(i));
  fs::create_directories(dir);
  test::write_file(dir / "slant_range.tif", std::string(bytes, 'x'));
  const auto t0 = fs::file_time_type::clock::now() - std::chrono::hours(2);
  fs::last_write_time(dir, t0 + std::chrono::minutes(i));
}

std::vector<std::string> names_in(const fs::path& out) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(ProductFolders, NamesOfProductFolders) {
  EXPECT_TRUE(is_product_folder_name("products-run12"));
  for (const char* other : {"products-run", "products-run1a", "products-run-1", "products",
                            "my-products-run1", "products-run1/"}) {
    EXPECT_FALSE(is_product_folder_name(other)) << other;
  }
}

TEST(ProductFolders, OldestAreRemovedBeyondTheCount) {
  test::TempDir tmp;
  const fs::path out = tmp.path();
  // Modified in the order 3, 1, 2, 5, 4 (not the numbers' order).
  int minute = 0;
  for (const int i : {3, 1, 2, 5, 4}) {
    make_folder(out, i, 10);
    fs::last_write_time(out / ("products-run" + std::to_string(i)),
                        fs::file_time_type::clock::now() - std::chrono::minutes(60 - minute++));
  }
  fs::create_directories(out / "saved-scenes");
  test::write_file(out / "edited.toml", "x");
  const auto removed = prune_product_folders(out, out / "products-run4", {.max_folders = 2});
  EXPECT_EQ(removed, (std::vector<std::string>{"products-run3", "products-run1", "products-run2"}));
  EXPECT_EQ(names_in(out), (std::vector<std::string>{"edited.toml", "products-run4",
                                                     "products-run5", "saved-scenes"}));
}

TEST(ProductFolders, OldestAreRemovedBeyondTheBytesAndTheNewestStays) {
  test::TempDir tmp;
  const fs::path out = tmp.path();
  for (int i = 1; i <= 4; ++i) make_folder(out, i, 1000);
  // 4000 bytes in all, 2500 allowed: the two oldest go.
  auto removed =
      prune_product_folders(out, out / "products-run4", {.max_folders = 100, .max_bytes = 2500});
  EXPECT_EQ(removed, (std::vector<std::string>{"products-run1", "products-run2"}));
  // The one just written stays even when it alone is over the bound, and
  // even when it is the oldest.
  fs::last_write_time(out / "products-run4",
                      fs::file_time_type::clock::now() - std::chrono::hours(5));
  removed = prune_product_folders(out, out / "products-run4", {.max_folders = 1, .max_bytes = 10});
  EXPECT_EQ(removed, (std::vector<std::string>{"products-run3"}));
  EXPECT_EQ(names_in(out), (std::vector<std::string>{"products-run4"}));
  // Within both bounds: nothing removed.
  EXPECT_TRUE(prune_product_folders(out, out / "products-run4", {}).empty());
}

TEST(ProductFolders, SymlinkedFoldersAreNotFollowed) {
  test::TempDir tmp;
  const fs::path out = tmp.path() / "out";
  const fs::path elsewhere = tmp.path() / "elsewhere";
  fs::create_directories(out);
  fs::create_directories(elsewhere);
  test::write_file(elsewhere / "precious.txt", "keep me");
  fs::create_directory_symlink(elsewhere, out / "products-run1");
  make_folder(out, 2, 10);
  make_folder(out, 3, 10);
  prune_product_folders(out, out / "products-run3", {.max_folders = 1});
  EXPECT_TRUE(fs::exists(elsewhere / "precious.txt"));
}

}  // namespace
}  // namespace ris
