#include "ris/sensor/polarisation.h"

#include <array>
#include <cctype>
#include <stdexcept>
#include <utility>

namespace ris {

namespace {
constexpr std::array<std::pair<std::string_view, Polarisation>, 4> kPolarisations = {{
    {"HH", Polarisation::HH},
    {"VV", Polarisation::VV},
    {"HV", Polarisation::HV},
    {"VH", Polarisation::VH},
}};
}  // namespace

Polarisation parse_polarisation(std::string_view text) {
  std::string up;
  for (char c : text) up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  for (const auto& [name, p] : kPolarisations)
    if (up == name) return p;
  throw std::invalid_argument("unknown polarisation \"" + std::string(text) +
                              "\" (expected HH, VV, HV or VH)");
}

std::string_view to_string(Polarisation p) {
  for (const auto& [name, value] : kPolarisations)
    if (value == p) return name;
  return "?";
}

}  // namespace ris
