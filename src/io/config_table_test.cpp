#include "ris/io/config_table.h"

#include <gtest/gtest.h>

#include <string>

#include "ris/util/error.h"

namespace ris {
namespace {

enum class Shape { round, square, flat };
Shape shape(ConfigTable& t, const std::string& key) {
  return t.get_enum<Shape>(
      key, {{"round", Shape::round}, {"square", Shape::square}, {"flat", Shape::flat}});
}

TEST(ConfigTableEnum, MapsTextFallsBackAndListsTheAllowedValues) {
  const toml::table doc = toml::parse(R"(a = "square"
b = "oval"
c = 3
)");
  ConfigTable t(doc, "f.toml", "shape");
  EXPECT_EQ(shape(t, "a"), Shape::square);
  EXPECT_EQ(t.get_enum_or<Shape>("missing", {{"round", Shape::round}}, Shape::flat), Shape::flat);
  try {
    shape(t, "b");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "f.toml");
    EXPECT_EQ(e.key(), "shape.b");
    EXPECT_NE(std::string(e.what()).find(R"(expected "round", "square" or "flat", got "oval")"),
              std::string::npos)
        << e.what();
  }
  EXPECT_THROW(shape(t, "c"), InputError);  // not a string
  EXPECT_THROW(shape(t, "missing"), InputError);
}

TEST(ConfigTableEnum, QuotedAlternatives) {
  EXPECT_EQ(quoted_alternatives({"a"}), R"("a")");
  EXPECT_EQ(quoted_alternatives({"a", "b"}), R"("a" or "b")");
  EXPECT_EQ(quoted_alternatives({"a", "b", "c"}), R"("a", "b" or "c")");
}

}  // namespace
}  // namespace ris
