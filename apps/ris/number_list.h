// Lists of numbers on the command line, shared by `ris sigma0` (--angles)
// and `ris dielectric` (--moisture): "start:stop:step" (inclusive) or
// "a,b,c"; items trimmed; bad text an InputError naming the option.
#pragma once

#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ris/util/error.h"
#include "ris/util/resource_guard.h"

namespace ris::app {

// Items of s separated by sep, trimmed of blanks; empty items dropped.
inline std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(s);
  while (std::getline(in, item, sep)) {
    const auto a = item.find_first_not_of(" \t");
    const auto b = item.find_last_not_of(" \t");
    if (a != std::string::npos) out.push_back(item.substr(a, b - a + 1));
  }
  return out;
}

inline double parse_double(const std::string& text, const std::string& option) {
  try {
    size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(v)) throw std::invalid_argument("");
    return v;
  } catch (const std::exception&) {
    throw InputError("", option, "expected a number, got \"" + text + "\"");
  }
}

// "start:stop:step" (inclusive) or "a,b,c"; `unit` names the values' unit in
// the message for a malformed range.
inline std::vector<double> parse_number_list(const std::string& text, const std::string& option,
                                             const std::string& unit) {
  std::vector<double> out;
  if (text.find(':') != std::string::npos) {
    const auto parts = split(text, ':');
    if (parts.size() != 3) throw InputError("", option, "expected start:stop:step in " + unit);
    const double a = parse_double(parts[0], option);
    const double b = parse_double(parts[1], option);
    const double step = parse_double(parts[2], option);
    if (!(step > 0.0) || b < a) throw InputError("", option, "expected start <= stop and step > 0");
    // At most a million values: a step of 1e-9 once hung the command.
    const std::int64_t n = checked_count(std::floor((b - a) / step + 1e-9), 1000000, "", option,
                                         "values (start:stop:step)");
    out.reserve(static_cast<std::size_t>(n) + 1);
    for (std::int64_t i = 0; i <= n; ++i) out.push_back(a + static_cast<double>(i) * step);
  } else {
    for (const auto& s : split(text, ',')) out.push_back(parse_double(s, option));
  }
  return out;
}

}  // namespace ris::app
