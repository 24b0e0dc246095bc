#include "ris/serve/json_depth.h"

#include <fmt/format.h>

#include <algorithm>

#include "ris/util/error.h"

namespace ris {

std::size_t json_nesting_depth(const std::string& text) {
  std::size_t depth = 0;
  std::size_t deepest = 0;
  bool in_string = false;
  bool escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) {
        escaped = false;
      } else if (c == '\\') {
        escaped = true;
      } else if (c == '"') {
        in_string = false;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

void check_json_depth(const std::string& text, const std::string& source, std::size_t max_depth) {
  const std::size_t depth = json_nesting_depth(text);
  if (depth > max_depth) {
    throw InputError(source, "",
                     fmt::format("JSON nested {} levels deep; at most {} are accepted (no "
                                 "request needs more: send the radar or object keys as in "
                                 "the TOML file)",
                                 depth, max_depth));
  }
}

}  // namespace ris
