// What the hostile-input tests assert of a refused run: its exit status,
// the text that names the fault, and a folder left as it was.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <set>
#include <string>

#include "build_paths.h"
#include "test_util.h"

namespace ris::test {

// Every name in a folder (to show a refused run left nothing).
inline std::set<std::string> listing(const std::filesystem::path& dir) {
  std::set<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    out.insert(e.path().filename().string());
  }
  return out;
}

// A shipped data file's path.
inline std::string data(const std::string& relative) {
  return std::string(data_dir()) + "/" + relative;
}

// The run failed with `status`, said `text`, and left the folder as it was.
inline void expect_refused(const RunResult& r, int status, const std::string& text,
                           const std::filesystem::path& dir, const std::set<std::string>& before) {
  EXPECT_EQ(r.exit_code, status) << r.output;
  EXPECT_THAT(r.output, ::testing::HasSubstr(text));
  EXPECT_EQ(listing(dir), before) << r.output;
}

}  // namespace ris::test
