#include "ris/backscatter/polarisation.h"

#include <cctype>
#include <stdexcept>

namespace ris {

Polarisation parse_polarisation(std::string_view text) {
  std::string up;
  for (char c : text) up += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  if (up == "HH") return Polarisation::HH;
  if (up == "VV") return Polarisation::VV;
  if (up == "HV") return Polarisation::HV;
  if (up == "VH") return Polarisation::VH;
  throw std::invalid_argument("unknown polarisation \"" + std::string(text) +
                              "\" (expected HH, VV, HV or VH)");
}

std::string_view to_string(Polarisation p) {
  switch (p) {
    case Polarisation::HH:
      return "HH";
    case Polarisation::VV:
      return "VV";
    case Polarisation::HV:
      return "HV";
    case Polarisation::VH:
      return "VH";
  }
  return "?";
}

}  // namespace ris
