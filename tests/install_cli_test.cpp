// The installed layout (`cmake --install`: <prefix>/bin/ris and
// <prefix>/share/ris/data): a ris there finds its data next to itself, from
// any working folder, without RIS_DATA.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "build_paths.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;
using test::q;

TEST(InstallCli, AnInstalledRisFindsItsDataNextToItself) {
  test::TempDir prefix;
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "share" / "ris");
  fs::copy_file(test::ris_exe(), prefix / "bin" / "ris");
  fs::create_directory_symlink(test::data_dir(), prefix / "share" / "ris" / "data");
  const std::string cmd = "cd " + q(prefix.path()) + " && env -u RIS_DATA " +
                          q(prefix / "bin" / "ris") + " simulate --quiet --out out > log.txt 2>&1";
  ASSERT_EQ(std::system(cmd.c_str()), 0) << test::read_file(prefix / "log.txt");
  const std::string log = test::read_file(prefix / "log.txt");
  EXPECT_THAT(log, ::testing::HasSubstr((prefix / "share" / "ris" / "data" / "scenes").string()));
  EXPECT_TRUE(fs::exists(prefix / "out" / "metadata.json"));
}

}  // namespace
}  // namespace ris
