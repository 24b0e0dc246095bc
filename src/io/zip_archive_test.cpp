// zip_files: every file comes back from the archive with its content.
#include "ris/io/zip_archive.h"

#include <cpl_vsi.h>
#include <gtest/gtest.h>

#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

std::string read_vsi(const std::string& path) {
  VSILFILE* f = VSIFOpenL(path.c_str(), "rb");
  if (f == nullptr) return "<missing>";
  std::string out;
  char buf[4096];
  for (std::size_t n; (n = VSIFReadL(buf, 1, sizeof buf, f)) > 0;) out.append(buf, n);
  VSIFCloseL(f);
  return out;
}

TEST(ZipArchive, FilesComeBackByName) {
  test::TempDir tmp;
  const std::string big(100000, 'x');
  test::write_file(tmp / "a.txt", "alpha");
  test::write_file(tmp / "b.json", big);
  const std::vector<std::uint8_t> zip = zip_files({tmp / "a.txt", tmp / "b.json"});
  ASSERT_GT(zip.size(), 20u);
  EXPECT_LT(zip.size(), big.size() / 10);  // deflated
  test::write_file(tmp / "out.zip", std::string(zip.begin(), zip.end()));
  const std::string root = "/vsizip/" + (tmp / "out.zip").string();
  EXPECT_EQ(read_vsi(root + "/a.txt"), "alpha");
  EXPECT_EQ(read_vsi(root + "/b.json"), big);
}

}  // namespace
}  // namespace ris
