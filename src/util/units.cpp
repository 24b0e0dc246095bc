#include "ris/util/units.h"

#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

namespace ris {

namespace {

struct UnitEntry {
  Quantity quantity;
  std::string_view name;
  double to_si;  // multiply a value in this unit by to_si to get SI
};

// Angles: SI is radians; a bare number is degrees.
constexpr std::array kUnits{
    UnitEntry{Quantity::length, "m", 1.0},
    UnitEntry{Quantity::length, "km", 1000.0},
    UnitEntry{Quantity::length, "cm", 0.01},
    UnitEntry{Quantity::length, "mm", 0.001},
    UnitEntry{Quantity::length, "ft", kFeetToMetres},
    UnitEntry{Quantity::length, "mi", 1609.344},
    UnitEntry{Quantity::length, "nmi", 1852.0},
    UnitEntry{Quantity::frequency, "Hz", 1.0},
    UnitEntry{Quantity::frequency, "kHz", 1e3},
    UnitEntry{Quantity::frequency, "MHz", 1e6},
    UnitEntry{Quantity::frequency, "GHz", 1e9},
    UnitEntry{Quantity::time, "s", 1.0},
    UnitEntry{Quantity::time, "ms", 1e-3},
    UnitEntry{Quantity::time, "us", 1e-6},
    UnitEntry{Quantity::time, "ns", 1e-9},
    UnitEntry{Quantity::angle, "deg", kPi / 180.0},
    UnitEntry{Quantity::angle, "rad", 1.0},
    UnitEntry{Quantity::angle, "mrad", 1e-3},
    UnitEntry{Quantity::power, "W", 1.0},
    UnitEntry{Quantity::power, "kW", 1e3},
    UnitEntry{Quantity::power, "MW", 1e6},
    UnitEntry{Quantity::power, "mW", 1e-3},
    UnitEntry{Quantity::speed, "m/s", 1.0},
    UnitEntry{Quantity::speed, "km/h", 1000.0 / 3600.0},
    UnitEntry{Quantity::speed, "kn", 1852.0 / 3600.0},
    UnitEntry{Quantity::speed, "ft/s", kFeetToMetres},
};

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

}  // namespace

std::string_view default_unit(Quantity q) {
  switch (q) {
    case Quantity::length:
      return "m";
    case Quantity::frequency:
      return "Hz";
    case Quantity::time:
      return "s";
    case Quantity::angle:
      return "deg";
    case Quantity::power:
      return "W";
    case Quantity::speed:
      return "m/s";
    case Quantity::dimensionless:
      return "";
  }
  return "";
}

double from_default_unit(double value, Quantity q) {
  return q == Quantity::angle ? deg_to_rad(value) : value;
}

std::string accepted_units(Quantity q) {
  std::string out;
  for (const auto& u : kUnits) {
    if (u.quantity != q) continue;
    if (!out.empty()) out += ", ";
    out += u.name;
  }
  return out.empty() ? std::string("none") : out;
}

double parse_quantity(std::string_view text, Quantity q) {
  std::string_view s = trim(text);
  double value = 0.0;
  const char* begin = s.data();
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc{} || ptr == begin) {
    throw std::invalid_argument("expected a number with an optional unit, got \"" +
                                std::string(text) + "\"");
  }
  if (!std::isfinite(value)) {
    throw std::invalid_argument("expected a finite number, got \"" + std::string(text) + "\"");
  }
  std::string_view unit = trim(std::string_view(ptr, static_cast<size_t>(end - ptr)));
  if (unit.empty()) return from_default_unit(value, q);
  for (const auto& u : kUnits) {
    if (u.quantity == q && u.name == unit) return value * u.to_si;
  }
  throw std::invalid_argument("unknown unit \"" + std::string(unit) +
                              "\" (accepted: " + accepted_units(q) + ")");
}

}  // namespace ris
