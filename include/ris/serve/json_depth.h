// The nesting depth of JSON text, counted before any parser sees it:
// nlohmann's parser (and the conversion to TOML after it) recurse once per
// level, so 30,000 nested brackets (60 KB, well under the body cap) would
// overflow a worker thread's stack and kill the server. A flat scan of the
// brackets outside strings costs one pass and no recursion.
//
// Example:
//   ris::check_json_depth(body, "request body", ris::kMaxJsonDepth);  // InputError when deeper
#pragma once

#include <cstddef>
#include <string>

namespace ris {

// Deeper than any request the page or the API needs (a radar override is 3
// or 4 levels) and far below what a thread's stack holds.
constexpr std::size_t kMaxJsonDepth = 64;

// The deepest nesting of arrays and objects in `text` ('[' and '{' outside
// strings; escapes inside strings honoured). Text that is not JSON still gets
// a number; the parser reports its errors afterwards.
std::size_t json_nesting_depth(const std::string& text);

// Throws InputError naming `source` when the nesting exceeds `max_depth`.
void check_json_depth(const std::string& text, const std::string& source, std::size_t max_depth);

}  // namespace ris
