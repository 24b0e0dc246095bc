// Helpers of the tests that compare whole output folders (a streamed or an
// MPI run against the in-memory, single-process run: byte for byte), and
// the shipped radars with one line of their text edited.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "build_paths.h"
#include "test_util.h"

namespace ris::test {

// A shipped radar file (data/radars/`from`) with old_text replaced by
// new_text, written as dir/name.
inline std::string radar_with(const TempDir& dir, const std::string& name, const std::string& from,
                              const std::string& old_text, const std::string& new_text) {
  namespace fs = std::filesystem;
  std::string text = read_file(fs::path(data_dir()) / "radars" / from);
  const auto at = text.find(old_text);
  EXPECT_NE(at, std::string::npos) << old_text;
  if (at != std::string::npos) text.replace(at, old_text.size(), new_text);
  const fs::path p = dir / name;
  write_file(p, text);
  return p.string();
}

// The products of `out` and `ref`: the same files, byte for byte, and at
// least min_files of them.
inline void expect_same_files(const std::filesystem::path& ref, const std::filesystem::path& out,
                              const std::string& tag, int min_files = 10) {
  namespace fs = std::filesystem;
  int files = 0;
  for (const auto& e : fs::directory_iterator(ref)) {
    const fs::path other = out / e.path().filename();
    ASSERT_TRUE(fs::exists(other)) << tag << ": " << other;
    EXPECT_TRUE(read_file(e.path()) == read_file(other)) << tag << ": " << e.path().filename();
    ++files;
  }
  int others = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++others;
  EXPECT_EQ(files, others) << tag;
  EXPECT_GE(files, min_files) << tag;
}

}  // namespace ris::test
