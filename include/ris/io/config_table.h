// Checked access to one TOML table: the edge where configuration text becomes
// plain structs (DESIGN.md principle 2).
//
// Every getter records the key as used; finish() rejects any key that was
// never asked for, so a misspelled key fails loudly (pbrt's ReportUnused).
// Errors are InputError naming the file and the dotted key path.
//
// Example:
//   ris::ConfigTable grid(doc, "scene.toml", "grid");
//   int rows = grid.get_int("rows");
//   double cell_m = grid.get_quantity("cell_size", ris::Quantity::length);
//   grid.finish();
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "ris/util/spelling.h"
#include "ris/util/units.h"

namespace ris {

// An enum's values as written in a file, each with its text: {"slar",
// RadarMode::slar}, ...
template <typename E>
using EnumChoices = std::initializer_list<std::pair<std::string_view, E>>;

// Whether two texts are equal without regard to (ASCII) case.
bool same_letters(std::string_view a, std::string_view b);

// The allowed texts for a message: "\"a\", \"b\" or \"c\"".
std::string quoted_alternatives(const std::vector<std::string_view>& texts);

// Parses a TOML file; a syntax error becomes an InputError with line/column.
// Refused before parsing: a file over kMaxTomlFileBytes, and one nesting
// deeper than kMaxTomlNesting levels (ris/io/toml_nesting.h).
toml::table parse_toml_file(const std::string& path);
// The same for TOML text from elsewhere (Python, a command-line option);
// source names it in messages.
toml::table parse_toml_text(std::string_view text, const std::string& source);

// The largest configuration file ris parses: 64 MiB (a scene of 5,000
// objects is 0.3 MB; the parser holds the whole text and its tree).
constexpr std::uintmax_t kMaxTomlFileBytes = std::uintmax_t{64} << 20;

class ConfigTable {
 public:
  // table: the TOML table; file: its path, for messages; path: dotted key path
  // of this table ("" for the document root, "grid", "object[3]").
  ConfigTable(const toml::table& table, std::string file, std::string path);

  bool has(const std::string& key) const;
  // Every key present, in file order (for tables keyed by the user, such as
  // id -> name maps).
  std::vector<std::string> keys() const;

  // Required values: throw InputError when missing or of the wrong type.
  double get_double(const std::string& key);
  std::int64_t get_int(const std::string& key);
  bool get_bool(const std::string& key);
  std::string get_string(const std::string& key);
  // A quantity written as a bare number (default unit) or "<number> <unit>";
  // returns SI (radians for angles).
  double get_quantity(const std::string& key, Quantity q);
  // An array of numbers (or quantities).
  std::vector<double> get_double_array(const std::string& key);
  std::vector<double> get_quantity_array(const std::string& key, Quantity q);

  // One of a fixed set of strings, as its enum value; anything else throws
  // InputError "expected \"a\", \"b\" or \"c\", got \"x\"".
  template <typename E>
  E get_enum(const std::string& key, EnumChoices<E> choices) {
    return enum_from(key, get_string(key), choices);
  }
  template <typename E>
  E get_enum_or(const std::string& key, EnumChoices<E> choices, E fallback) {
    return has(key) ? get_enum(key, choices) : fallback;
  }
  // The same from a registry kept elsewhere (a table of names that other
  // lists read too, e.g. ris/backscatter/dielectric.h's).
  template <typename E>
  E get_registered_enum(const std::string& key,
                        std::span<const std::pair<std::string_view, E>> registry) {
    return enum_from(key, get_string(key), registry);
  }
  template <typename E>
  E get_registered_enum_or(const std::string& key,
                           std::span<const std::pair<std::string_view, E>> registry, E fallback) {
    return has(key) ? get_registered_enum(key, registry) : fallback;
  }

  // Optional values: return the default (or nullopt) when absent.
  double get_double_or(const std::string& key, double fallback);
  std::int64_t get_int_or(const std::string& key, std::int64_t fallback);
  bool get_bool_or(const std::string& key, bool fallback);
  std::string get_string_or(const std::string& key, const std::string& fallback);
  double get_quantity_or(const std::string& key, Quantity q, double fallback_si);
  std::optional<double> get_quantity_opt(const std::string& key, Quantity q);
  std::optional<std::string> get_string_opt(const std::string& key);

  // Sub-tables and arrays of tables, marked as used.
  std::optional<ConfigTable> subtable(const std::string& key);
  std::vector<ConfigTable> table_array(const std::string& key);

  // Marks a key as used without reading it (for keys handled elsewhere).
  void mark_used(const std::string& key);

  // Throws InputError listing every key present but never read.
  void finish() const;

  // The raw node (marks it used), for callers with their own type logic.
  const toml::node* raw(const std::string& key);

  const std::string& file() const { return file_; }
  // Dotted path of a key in this table, for messages: "grid.cell_size".
  std::string key_path(const std::string& key) const;
  // An InputError about a key of this table.
  [[noreturn]] void fail(const std::string& key, const std::string& what) const;

 private:
  const toml::node& require(const std::string& key);
  // choices: pairs (text, value), an EnumChoices or a registry's span.
  template <typename Choices>
  auto enum_from(const std::string& key, const std::string& text, const Choices& choices) const
      -> std::remove_cvref_t<decltype(choices.begin()->second)> {
    // Without regard to case, as polarisations are ("Right" is "right").
    std::vector<std::string_view> texts;
    std::vector<std::string> names;
    for (const auto& [t, value] : choices) {
      if (same_letters(t, text)) return value;
      texts.push_back(t);
      names.emplace_back(t);
    }
    fail(key, "expected " + quoted_alternatives(texts) + ", got \"" + text + "\"" +
                  did_you_mean(text, names));
  }

  const toml::table* table_;
  std::string file_;
  std::string path_;
  std::set<std::string> used_;
  mutable std::set<std::string> asked_;  // every key looked up: the did-you-mean candidates
};

}  // namespace ris
