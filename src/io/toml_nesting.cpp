#include "ris/io/toml_nesting.h"

#include <fmt/format.h>

#include <vector>

#include "ris/util/error.h"

namespace ris {

namespace {

// One pass over the text (the header's comment says what is counted). Any
// text that is not TOML is passed over one character at a time, never
// judged: the parser that runs next reports the syntax error with its line.
class NestingScan {
 public:
  NestingScan(std::string_view text, std::size_t max_depth) : t_(text), max_(max_depth) {
    open_.reserve(max_depth + 1);
  }

  // The line of the first level past max_depth, or 0.
  std::size_t first_line_too_deep() {
    while (!at_end()) {
      const std::size_t before = i_;
      skip_blank(true);
      if (at_end()) break;
      if (!(peek() == '[' ? header() : key_value())) return line_;
      if (i_ == before) advance();  // no TOML here: step over it
    }
    return 0;
  }

 private:
  struct Open {
    char kind;          // '[' an array, '{' an inline table
    std::size_t level;  // the container's own level
  };

  bool at_end() const { return i_ >= t_.size(); }
  char peek(std::size_t k = 0) const { return i_ + k < t_.size() ? t_[i_ + k] : '\0'; }
  void advance() {
    if (t_[i_] == '\n') ++line_;
    ++i_;
  }

  // Spaces and tabs; with `lines`, also newlines and comments.
  void skip_blank(bool lines) {
    while (!at_end()) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || (lines && c == '\n')) {
        advance();
      } else if (lines && c == '#') {
        while (!at_end() && peek() != '\n') advance();
      } else {
        return;
      }
    }
  }

  // At a quote: past the string (basic, literal, or either multi-line).
  void skip_string() {
    const char q = peek();
    const bool multi = peek(1) == q && peek(2) == q;
    const std::size_t quotes = multi ? 3 : 1;
    for (std::size_t k = 0; k < quotes; ++k) advance();
    while (!at_end()) {
      const char c = peek();
      if (c == '\\' && q == '"') {
        advance();
        if (!at_end()) advance();
      } else if (c == q && (!multi || (peek(1) == q && peek(2) == q))) {
        for (std::size_t k = 0; k < quotes; ++k) advance();
        // """a"""" ends with a quote in the string: up to two more.
        for (int extra = 0; multi && extra < 2 && peek() == q; ++extra) advance();
        return;
      } else if (c == '\n' && !multi) {
        return;  // unterminated: the parser says so
      } else {
        advance();
      }
    }
  }

  static bool bare_key_char(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-';
  }

  // A (dotted) key up to and including `end` ('=' or ']'): its parts.
  std::size_t key_parts(char end) {
    std::size_t parts = 1;
    while (!at_end()) {
      skip_blank(false);
      const char c = peek();
      if (c == '"' || c == '\'') {
        skip_string();
      } else if (bare_key_char(c)) {
        while (!at_end() && bare_key_char(peek())) advance();
      } else if (c == '.') {
        ++parts;
        advance();
      } else {
        if (c == end) advance();
        return parts;  // the end, or not a key: the parser reports it
      }
    }
    return parts;
  }

  // [table] or [[array of tables]]: sets the level of the keys below it.
  bool header() {
    const bool array = peek(1) == '[';
    advance();
    if (array) advance();
    header_level_ = key_parts(']') + (array ? 1 : 0);
    if (array && peek() == ']') advance();
    return header_level_ <= max_;
  }

  bool key_value() {
    const std::size_t level = header_level_ + key_parts('=');
    return level <= max_ && value(level);
  }

  // A number, date, boolean or string: passed over.
  void skip_scalar() {
    if (peek() == '"' || peek() == '\'') {
      skip_string();
      return;
    }
    while (!at_end()) {
      const char c = peek();
      if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',' || c == ']' || c == '}' ||
          c == '#' || c == '[' || c == '{') {
        return;
      }
      advance();
    }
  }

  // Opens an array or inline table at `level`; sets `level` to the level of
  // its first value. False when that is past the limit.
  bool open(char kind, std::size_t& level) {
    advance();
    open_.push_back({kind, level});
    skip_blank(true);
    if (peek() == (kind == '[' ? ']' : '}')) return true;  // empty: closed by after_value
    level = kind == '[' ? level + 1 : level + key_parts('=');
    return level <= max_;
  }

  enum class Next { done, value, too_deep };

  // After a value: closes containers until a ',' leads to the next value
  // (setting `level`) or the outermost value is complete.
  Next after_value(std::size_t& level) {
    while (!open_.empty() && !at_end()) {
      skip_blank(true);
      const char c = peek();
      const Open top = open_.back();
      if (c == (top.kind == '[' ? ']' : '}')) {
        advance();
        open_.pop_back();
      } else if (c == ',') {
        advance();
        skip_blank(true);
        if (peek() == ']' || peek() == '}') continue;  // a trailing comma
        level = top.kind == '[' ? top.level + 1 : top.level + key_parts('=');
        return level <= max_ ? Next::value : Next::too_deep;
      } else if (!at_end()) {
        advance();  // not TOML: step over it
      }
    }
    return Next::done;
  }

  // One value at `level`, arrays and inline tables iteratively (an explicit
  // stack of at most max_depth entries, never recursion).
  bool value(std::size_t level) {
    open_.clear();
    for (;;) {
      skip_blank(!open_.empty());
      const char c = peek();
      const std::size_t depth_before = open_.size();
      if (c == '[' || c == '{') {
        if (!open(c, level)) return false;
        const char close = c == '[' ? ']' : '}';
        if (open_.size() > depth_before && peek() != close) continue;  // its first value
      } else {
        skip_scalar();
      }
      switch (after_value(level)) {
        case Next::done:
          return true;
        case Next::too_deep:
          return false;
        case Next::value:
          break;
      }
    }
  }

  std::string_view t_;
  std::size_t max_;
  std::size_t i_ = 0;
  std::size_t line_ = 1;
  std::size_t header_level_ = 0;
  std::vector<Open> open_;
};

}  // namespace

std::optional<std::size_t> toml_line_deeper_than(std::string_view text, std::size_t max_depth) {
  NestingScan scan(text, max_depth);
  const std::size_t line = scan.first_line_too_deep();
  if (line == 0) return std::nullopt;
  return line;
}

void require_toml_nesting_within(std::string_view text, std::size_t max_depth,
                                 const std::string& source) {
  if (const std::optional<std::size_t> line = toml_line_deeper_than(text, max_depth)) {
    throw InputError(source, "",
                     fmt::format("line {} nests tables, keys or arrays more than {} levels deep "
                                 "(table headers and dotted keys count each part); no ris file "
                                 "needs more than a few: is this the right file?",
                                 *line, max_depth));
  }
}

}  // namespace ris
