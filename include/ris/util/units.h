// Physical quantities written with units in configuration files.
//
// Configuration values may be a bare number (taken in the quantity's SI unit,
// except angles, which are degrees by convention in this field) or a string
// "<number> <unit>", e.g. "20 ft", "8.6 GHz", "0.163 us", "6.8e-4 rad".
// An unknown unit is an error, never a silent guess (MODEL.md, preamble).
//
// Example:
//   double cell_m = ris::parse_quantity("20 ft", ris::Quantity::length);  // 6.096
#pragma once

#include <string>
#include <string_view>

namespace ris {

enum class Quantity { length, frequency, time, angle, power, speed, dimensionless };

// The unit a bare number is taken in: metres, hertz, seconds, degrees, watts,
// metres per second, or none.
std::string_view default_unit(Quantity q);

// Parses "<number> [unit]" and returns the value in SI units (radians for
// angles). Throws std::invalid_argument with a message listing the accepted
// units; callers wrap it into an InputError naming file and key.
double parse_quantity(std::string_view text, Quantity q);

// Converts a bare number written in the default unit to SI (degrees -> radians
// for angles; identity otherwise).
double from_default_unit(double value, Quantity q);

// The accepted unit names for a quantity, for error messages.
std::string accepted_units(Quantity q);

constexpr double kFeetToMetres = 0.3048;
constexpr double kSpeedOfLight_m_per_s = 299792458.0;
constexpr double kPi = 3.14159265358979323846;

constexpr double deg_to_rad(double deg) {
  return deg * kPi / 180.0;
}
constexpr double rad_to_deg(double rad) {
  return rad * 180.0 / kPi;
}

}  // namespace ris
