// The pre-scan of JSON nesting (ris/serve/json_depth.h) and its use before
// parsing a request body.
#include "ris/serve/json_depth.h"

#include <gtest/gtest.h>

#include "ris/serve/json_toml.h"
#include "ris/util/error.h"

namespace ris {
namespace {

TEST(JsonDepth, CountsBracketsOutsideStrings) {
  EXPECT_EQ(json_nesting_depth("1"), 0u);
  EXPECT_EQ(json_nesting_depth("{}"), 1u);
  EXPECT_EQ(json_nesting_depth(R"({"a": [1, {"b": [[]]}], "c": {}})"), 5u);
  EXPECT_EQ(json_nesting_depth(R"({"a": "[[[{{{"})"), 1u);
  EXPECT_EQ(json_nesting_depth(R"({"a": "\"[[[", "b": [2]})"), 2u);  // escaped quote
  EXPECT_EQ(json_nesting_depth(R"({"a": "\\", "b": [[3]]})"), 3u);   // escaped backslash
  EXPECT_EQ(json_nesting_depth("]]]]{"), 1u);                        // not JSON: still a number
  EXPECT_EQ(json_nesting_depth(std::string(30000, '[')), 30000u);
}

TEST(JsonDepth, DeepBodiesAreRefusedBeforeParsing) {
  const auto nested = [](std::size_t levels) {
    return std::string(levels - 1, '[') + "1" + std::string(levels - 1, ']');
  };
  // {"a": <levels - 1 arrays>}: `levels` in all.
  const auto body = [&](std::size_t levels) { return R"({"a": )" + nested(levels) + "}"; };
  EXPECT_NO_THROW(json_body_to_toml(body(kMaxJsonDepth), "request body"));
  try {
    json_body_to_toml(body(kMaxJsonDepth + 1), "request body");
    FAIL() << "65 levels accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("nested 65 levels deep; at most 64"), std::string::npos)
        << e.what();
    EXPECT_EQ(e.file(), "request body");
  }
  // 30,000 levels: refused, not a stack overflow.
  EXPECT_THROW(json_body_to_toml(body(30000), "request body"), InputError);
}

}  // namespace
}  // namespace ris
