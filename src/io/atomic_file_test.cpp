// StagedDirectory's staging folders removed from outside the writer
// (remove_staged_directories: an MPI rank stopped by mpirun's SIGTERM,
// apps/ris/mpi/mpi_process_group.cpp): every live one, with its files;
// a destroyed one is forgotten.
#include "ris/io/atomic_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

// The hidden staging folders in `dir` (".name.partial-...").
std::vector<std::string> staging_folders(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().starts_with(".")) names.push_back(e.path().filename());
  return names;
}

TEST(StagedDirectory, RemoveStagedDirectoriesRemovesEveryLiveStagingFolder) {
  test::TempDir dir;
  std::optional<StagedDirectory> a(std::in_place, dir / "a");
  {
    StagedDirectory gone(dir / "gone");  // destroyed: its folder removed, forgotten
  }
  StagedDirectory b(dir / "b");
  write_text_file_atomic(a->path("x.txt"), "x");
  write_text_file_atomic(b.path("y.txt"), "y");
  EXPECT_EQ(staging_folders(dir.path()).size(), 2u);
  remove_staged_directories();
  EXPECT_TRUE(staging_folders(dir.path()).empty());
  EXPECT_FALSE(fs::exists(dir / "a"));
  EXPECT_FALSE(fs::exists(dir / "b"));
  a.reset();  // its destructor finds nothing to remove
  remove_staged_directories();
  EXPECT_TRUE(staging_folders(dir.path()).empty());
}

}  // namespace
}  // namespace ris
