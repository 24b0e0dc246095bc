// Answers name files, not the server's folders (ris/serve/client_paths.h).
#include "ris/serve/client_paths.h"

#include <gtest/gtest.h>

namespace ris {
namespace {

TEST(ClientPaths, AbsolutePathsLoseTheirFolders) {
  EXPECT_EQ(without_directories("/home/me/radars/x.toml: frequency: expected a frequency"),
            "x.toml: frequency: expected a frequency");
  EXPECT_EQ(without_directories("cannot open \"/srv/data/dem.tif\" (missing)"),
            "cannot open \"dem.tif\" (missing)");
  EXPECT_EQ(without_directories("in /tmp/out/, twice: /a/b and (/c/d)"),
            "in out, twice: b and (d)");
  EXPECT_EQ(without_directories("path=/etc/passwd"), "path=passwd");
  // Not paths: left as they are.
  EXPECT_EQ(without_directories("speed 3 m/s, 1/2 of data/radars/x.toml"),
            "speed 3 m/s, 1/2 of data/radars/x.toml");
  EXPECT_EQ(without_directories("a / b"), "a / b");
  EXPECT_EQ(without_directories(""), "");
}

}  // namespace
}  // namespace ris
