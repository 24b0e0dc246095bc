// The TOML nesting pre-scan (ris/io/toml_nesting.h): every construct that
// nests counts, at exactly the limit a text passes and one past it fails,
// nothing inside strings or comments counts, and every TOML file ris ships
// is far inside the limit.
#include "ris/io/toml_nesting.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "build_paths.h"
#include "ris/io/config_table.h"
#include "ris/util/error.h"
#include "test_util.h"

namespace ris {
namespace {

namespace fs = std::filesystem;

std::string repeat(const std::string& s, std::size_t n) {
  std::string out;
  for (std::size_t i = 0; i < n; ++i) out += s;
  return out;
}

// [a.a. ... .a] with n parts.
std::string header(std::size_t n) {
  return "[a" + repeat(".a", n - 1) + "]\nx = 1\n";
}
// k = [[ ... [1] ... ]] with n brackets: the innermost value at n + 1.
std::string arrays(std::size_t n) {
  return "k = " + repeat("[", n) + "1" + repeat("]", n) + "\n";
}
// k = { a = { a = ... { a = 1 } } } with n tables: the value at n + 1.
std::string inline_tables(std::size_t n) {
  return "k = " + repeat("{ a = ", n) + "1" + repeat(" }", n) + "\n";
}

TEST(TomlNesting, EachConstructCountsUpToTheLimitExactly) {
  const std::size_t max = 10;
  // header(n)'s key sits at n + 1: its line (2) is the one past the limit.
  EXPECT_FALSE(toml_line_deeper_than(header(max - 1), max));
  EXPECT_EQ(toml_line_deeper_than(header(max), max), 2u);
  EXPECT_EQ(toml_line_deeper_than(header(max + 1), max), 1u);
  EXPECT_FALSE(toml_line_deeper_than(arrays(max - 1), max));
  EXPECT_EQ(toml_line_deeper_than(arrays(max), max), 1u);
  EXPECT_FALSE(toml_line_deeper_than(inline_tables(max - 1), max));
  EXPECT_EQ(toml_line_deeper_than(inline_tables(max), max), 1u);
  // Dotted keys, an array of tables, and the sum of a header and its keys.
  EXPECT_FALSE(toml_line_deeper_than("a" + repeat(".a", max - 1) + " = 1\n", max));
  EXPECT_TRUE(toml_line_deeper_than("a" + repeat(".a", max) + " = 1\n", max));
  EXPECT_FALSE(toml_line_deeper_than("[[t" + repeat(".t", max - 3) + "]]\nx = 1\n", max));
  EXPECT_TRUE(toml_line_deeper_than("[[t" + repeat(".t", max - 1) + "]]\nx = 1\n", max));
  EXPECT_FALSE(toml_line_deeper_than("[a.b.c.d.e]\nf.g.h.i.j = 1\n", max));
  EXPECT_EQ(toml_line_deeper_than("[a.b.c.d.e]\n\nf.g.h.i.j.k = 1\n", max), 3u);
  // An inline table's keys add their parts; an array's elements go one deeper.
  EXPECT_TRUE(toml_line_deeper_than("[a.b.c.d]\nk = [{ x.y.z = [[1]] }]\n", 9));
  EXPECT_FALSE(toml_line_deeper_than("[a.b.c.d]\nk = [{ x.y.z = [[1]] }]\n", 11));
}

TEST(TomlNesting, StringsCommentsAndLaterValuesAreReadRight) {
  const std::string deep = repeat("[", 500) + repeat("{", 500) + repeat(".", 500);
  EXPECT_FALSE(toml_line_deeper_than("s = \"" + deep + "\"\n", 4));
  EXPECT_FALSE(toml_line_deeper_than("s = '" + deep + "'\n", 4));
  EXPECT_FALSE(toml_line_deeper_than("s = \"\"\"\n" + deep + "\n\"\" \\\"\"\"\"\n", 4));
  EXPECT_FALSE(toml_line_deeper_than("s = '''\n" + deep + "\n'''\n", 4));
  EXPECT_FALSE(toml_line_deeper_than("# " + deep + "\nx = 1\n", 4));
  EXPECT_FALSE(toml_line_deeper_than("\"a.b.c.d.e.f\" = 1\n", 2));
  EXPECT_FALSE(toml_line_deeper_than("s = \"esc \\\" [[[[[[\"\n", 2));
  // After such strings, the next line is counted again: its line number.
  EXPECT_EQ(toml_line_deeper_than("s = \"\"\"\n[[[\n\"\"\"\n# [[[[\nk = [[[1]]]\n", 3), 5u);
  // Arrays over lines, with comments and a trailing comma.
  EXPECT_FALSE(toml_line_deeper_than("k = [\n  1, # one\n  [2, 3],\n]\n", 3));
  EXPECT_EQ(toml_line_deeper_than("k = [\n  1,\n  [[[2]]],\n]\n", 3), 3u);
  // Empty containers and odd text never loop or throw.
  EXPECT_FALSE(toml_line_deeper_than("k = []\nt = {}\n]]]}}}\n= = =\n[\n", 3));
}

TEST(TomlNesting, HostileDepthsAreRefusedBeforeTheParser) {
  test::TempDir dir;
  // The crash: a header of 100,000 parts (toml++ recursed until the
  // stack ran out), and deep arrays and inline tables.
  for (const std::string& text : {header(100000), arrays(100000), inline_tables(100000)}) {
    const fs::path p = dir / "deep.toml";
    test::write_file(p, text);
    try {
      parse_toml_file(p.string());
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("more than 64 levels deep"));
      EXPECT_EQ(e.file(), p.string());
    }
  }
  EXPECT_THROW(parse_toml_text(arrays(kMaxTomlNesting), "<text>"), InputError);
  EXPECT_NO_THROW(parse_toml_text(arrays(kMaxTomlNesting - 1), "<text>"));
}

TEST(TomlNesting, OversizedFilesAreRefusedUnread) {
  test::TempDir dir;
  const fs::path p = dir / "big.toml";
  test::write_file(p, "x = 1\n");
  fs::resize_file(p, kMaxTomlFileBytes + 1);  // sparse: no disk used
  try {
    parse_toml_file(p.string());
    ADD_FAILURE() << "accepted";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("may have at most"));
  }
}

// The limit's comment says no ris file needs more than 7 levels.
TEST(TomlNesting, EveryShippedTomlFileIsShallow) {
  int files = 0;
  for (const std::string& root :
       {std::string(test::data_dir()), std::string(test::source_dir()) + "/tests"}) {
    for (const auto& e : fs::recursive_directory_iterator(root)) {
      if (e.path().extension() != ".toml") continue;
      ++files;
      EXPECT_FALSE(toml_line_deeper_than(test::read_file(e.path()), 7)) << e.path();
    }
  }
  EXPECT_GT(files, 20);
}

}  // namespace
}  // namespace ris
