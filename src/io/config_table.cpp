#include "ris/io/config_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "ris/io/safe_paths.h"
#include "ris/io/toml_nesting.h"
#include "ris/util/error.h"
#include "ris/util/spelling.h"

namespace ris {

bool same_letters(std::string_view a, std::string_view b) {
  return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

std::string quoted_alternatives(const std::vector<std::string_view>& texts) {
  std::string out;
  for (std::size_t i = 0; i < texts.size(); ++i) {
    if (i > 0) out += i + 1 == texts.size() ? " or " : ", ";
    out += "\"" + std::string(texts[i]) + "\"";
  }
  return out;
}

toml::table parse_toml_text(std::string_view text, const std::string& source) {
  // Before toml++'s recursive parser sees it (ris/io/toml_nesting.h).
  require_toml_nesting_within(text, kMaxTomlNesting, source);
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    throw InputError(source, "",
                     fmt::format("TOML syntax error at line {}, column {}: {}", where.line,
                                 where.column, e.description()));
  }
}

toml::table parse_toml_file(const std::string& path) {
  require_regular_input(path);  // a FIFO would block the parser forever
  std::error_code ec;
  const std::uintmax_t bytes = std::filesystem::file_size(path, ec);
  if (ec) throw InputError(path, "", "cannot read its size: " + ec.message());
  if (bytes > kMaxTomlFileBytes) {
    throw InputError(path, "",
                     fmt::format("is {} bytes; a ris configuration file (TOML) may have at most "
                                 "{} (docs/limits.md): is this the right file?",
                                 bytes, kMaxTomlFileBytes));
  }
  std::ifstream in(path, std::ios::binary);
  std::string text(static_cast<std::size_t>(bytes), '\0');
  if (!in || !in.read(text.data(), static_cast<std::streamsize>(text.size()))) {
    throw InputError(path, "", "cannot be read");
  }
  return parse_toml_text(text, path);
}

ConfigTable::ConfigTable(const toml::table& table, std::string file, std::string path)
    : table_(&table), file_(std::move(file)), path_(std::move(path)) {}

std::string ConfigTable::key_path(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void ConfigTable::fail(const std::string& key, const std::string& what) const {
  throw InputError(file_, key_path(key), what);
}

bool ConfigTable::has(const std::string& key) const {
  asked_.insert(key);
  return table_->contains(key);
}

std::vector<std::string> ConfigTable::keys() const {
  std::vector<std::string> out;
  for (const auto& [k, v] : *table_) out.emplace_back(k.str());
  return out;
}

void ConfigTable::mark_used(const std::string& key) {
  used_.insert(key);
  asked_.insert(key);
}

const toml::node* ConfigTable::raw(const std::string& key) {
  used_.insert(key);
  asked_.insert(key);
  return table_->get(key);
}

const toml::node& ConfigTable::require(const std::string& key) {
  used_.insert(key);
  asked_.insert(key);
  const toml::node* node = table_->get(key);
  if (node == nullptr) {
    // A key of the table that nothing has read and that is one slip from
    // this one ("polarization" for "polarisation"; one in six letters at
    // most, so that "far_range" is never taken for "near_range").
    std::vector<std::string> unread;
    for (const auto& [k, v] : *table_) {
      if (used_.count(std::string(k.str())) == 0) unread.emplace_back(k.str());
    }
    std::string hint;
    for (const std::string& name : unread) {
      if (edit_distance(name, key) <= std::max<std::size_t>(1, key.size() / 6)) {
        hint = fmt::format("; the table has \"{}\", which is not a key: did you mean \"{}\"?", name,
                           key);
        break;
      }
    }
    fail(key, "missing required key" + hint);
  }
  return *node;
}

double ConfigTable::get_double(const std::string& key) {
  const toml::node& node = require(key);
  if (auto v = node.value<double>(); v && (node.is_floating_point() || node.is_integer())) {
    if (!std::isfinite(*v)) fail(key, fmt::format("expected a finite number, got {}", *v));
    return *v;
  }
  fail(key, "expected a number");
}

std::int64_t ConfigTable::get_int(const std::string& key) {
  const toml::node& node = require(key);
  if (auto v = node.as_integer()) return v->get();
  fail(key, "expected an integer");
}

bool ConfigTable::get_bool(const std::string& key) {
  const toml::node& node = require(key);
  if (auto v = node.as_boolean()) return v->get();
  fail(key, "expected true or false");
}

std::string ConfigTable::get_string(const std::string& key) {
  const toml::node& node = require(key);
  if (auto v = node.as_string()) return v->get();
  fail(key, "expected a string");
}

namespace {
// Every quantity read from a file is finite, and a length is within
// kMaxLength_m of zero (a million km: past any orbit ris models, and small
// enough that a height stored as a float stays finite; 1e39 m would not).
constexpr double kMaxLength_m = 1e9;

double checked_quantity(double v, Quantity q, const ConfigTable& t, const std::string& key) {
  if (!std::isfinite(v)) t.fail(key, fmt::format("expected a finite value, got {}", v));
  if (q == Quantity::length && std::abs(v) > kMaxLength_m) {
    t.fail(key, fmt::format("{:g} m is out of physical bounds (expected at most {:g} m)", v,
                            kMaxLength_m));
  }
  return v;
}

double node_quantity(const toml::node& node, Quantity q, const ConfigTable& t,
                     const std::string& key) {
  if (node.is_integer() || node.is_floating_point()) {
    return checked_quantity(from_default_unit(*node.value<double>(), q), q, t, key);
  }
  if (auto s = node.as_string()) {
    try {
      return checked_quantity(parse_quantity(s->get(), q), q, t, key);
    } catch (const std::invalid_argument& e) {
      t.fail(key, e.what());
    }
  }
  t.fail(key, fmt::format("expected a number (in {}) or a string \"<number> <unit>\"",
                          default_unit(q).empty() ? "no unit" : default_unit(q)));
}
}  // namespace

double ConfigTable::get_quantity(const std::string& key, Quantity q) {
  return node_quantity(require(key), q, *this, key);
}

std::vector<double> ConfigTable::get_double_array(const std::string& key) {
  return get_quantity_array(key, Quantity::dimensionless);
}

std::vector<double> ConfigTable::get_quantity_array(const std::string& key, Quantity q) {
  const toml::node& node = require(key);
  const toml::array* arr = node.as_array();
  if (arr == nullptr) fail(key, "expected an array");
  std::vector<double> out;
  out.reserve(arr->size());
  for (const toml::node& element : *arr) out.push_back(node_quantity(element, q, *this, key));
  return out;
}

double ConfigTable::get_double_or(const std::string& key, double fallback) {
  return has(key) ? get_double(key) : fallback;
}
std::int64_t ConfigTable::get_int_or(const std::string& key, std::int64_t fallback) {
  return has(key) ? get_int(key) : fallback;
}
bool ConfigTable::get_bool_or(const std::string& key, bool fallback) {
  return has(key) ? get_bool(key) : fallback;
}
std::string ConfigTable::get_string_or(const std::string& key, const std::string& fallback) {
  return has(key) ? get_string(key) : fallback;
}
double ConfigTable::get_quantity_or(const std::string& key, Quantity q, double fallback_si) {
  return has(key) ? get_quantity(key, q) : fallback_si;
}
std::optional<double> ConfigTable::get_quantity_opt(const std::string& key, Quantity q) {
  if (!has(key)) return std::nullopt;
  return get_quantity(key, q);
}
std::optional<std::string> ConfigTable::get_string_opt(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return get_string(key);
}

std::optional<ConfigTable> ConfigTable::subtable(const std::string& key) {
  if (!has(key)) return std::nullopt;
  const toml::node& node = require(key);
  const toml::table* t = node.as_table();
  if (t == nullptr) fail(key, "expected a table");
  return ConfigTable(*t, file_, key_path(key));
}

std::vector<ConfigTable> ConfigTable::table_array(const std::string& key) {
  std::vector<ConfigTable> out;
  if (!has(key)) return out;
  const toml::node& node = require(key);
  const toml::array* arr = node.as_array();
  if (arr == nullptr) fail(key, "expected an array of tables ([[" + key + "]])");
  size_t index = 0;
  for (const toml::node& element : *arr) {
    const toml::table* t = element.as_table();
    if (t == nullptr) fail(key, fmt::format("element {} is not a table", index));
    out.emplace_back(*t, file_, fmt::format("{}[{}]", key_path(key), index));
    ++index;
  }
  return out;
}

void ConfigTable::finish() const {
  // What the reader asked for and the table lacks: the keys a slip may have
  // meant.
  std::vector<std::string> absent;
  for (const std::string& k : asked_) {
    if (!table_->contains(k)) absent.push_back(k);
  }
  std::string unknown;
  for (const auto& [k, v] : *table_) {
    std::string name(k.str());
    if (used_.count(name) == 0) {
      if (!unknown.empty()) unknown += ", ";
      unknown += key_path(name) + did_you_mean(name, absent);
    }
  }
  if (!unknown.empty()) {
    throw InputError(file_, "", "unknown key(s): " + unknown + " (check the spelling)");
  }
}

}  // namespace ris
