// How deeply a TOML text nests, found by a lexical pre-scan before any
// recursive parser sees it.
//
// toml++ parses table headers, dotted keys, arrays and inline tables by
// recursion, and builds (and later destroys) one nested table per level: a
// header of 100,000 dotted parts in a 0.3 MB file overflows the stack
// (SIGSEGV). The scan counts, for every value, the levels it sits under:
// the current [table] header's parts (+1 for an [[array of tables]]), the
// dotted parts of its key, and the arrays and inline tables around it, each
// inline table's keys adding their own parts. Strings (basic, literal and
// multi-line) and comments are skipped, so a '[' or '.' inside them does
// not count. The scan is linear, needs no memory past `max_depth` levels,
// and stops at the first line deeper than the limit.
//
// Example:
//   require_toml_nesting_within(text, kMaxTomlNesting, "scene.toml");
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace ris {

// The deepest nesting any ris file needs is 7 (a library's
// [category.band.model.ground.permittivity] keys, under the [[category]]
// array of tables); 64 leaves room for every hand-written
// file while staying far below the depth at which the parser's recursion
// could exhaust a thread's stack (docs/limits.md).
constexpr std::size_t kMaxTomlNesting = 64;

// The 1-based line of the first place where `text` nests deeper than
// max_depth levels, or nothing when it never does.
std::optional<std::size_t> toml_line_deeper_than(std::string_view text, std::size_t max_depth);

// InputError (source, line) when `text` nests deeper than max_depth.
void require_toml_nesting_within(std::string_view text, std::size_t max_depth,
                                 const std::string& source);

}  // namespace ris
