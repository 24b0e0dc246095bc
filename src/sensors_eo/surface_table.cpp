#include "ris/sensors_eo/surface_table.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "ris/backscatter/library.h"
#include "ris/scene/scene_source.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "ris/util/path_exists.h"

namespace ris {
namespace {

const std::vector<std::string> kColumns{
    "id",       "name",      "emissivity_lwir", "emissivity_mwir", "albedo", "thermal_inertia",
    "rho_blue", "rho_green", "rho_red",         "rho_nir"};

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) {
    const auto b = cell.find_first_not_of(" \t\r");
    const auto e = cell.find_last_not_of(" \t\r");
    out.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
  }
  return out;
}

double number(const std::string& cell, const std::string& path, const std::string& key) {
  char* end = nullptr;
  const double v = std::strtod(cell.c_str(), &end);
  if (cell.empty() || *end != '\0')
    throw InputError(path, key, "expected a number, got '" + cell + "'");
  return v;
}

double fraction(const std::string& cell, const std::string& path, const std::string& key) {
  const double v = number(cell, path, key);
  if (!(v >= 0.0 && v <= 1.0)) {
    throw InputError(path, key, "expected a value in [0, 1], got " + cell);
  }
  return v;
}

EoSurface parse_row(const std::vector<std::string>& c, const std::string& path,
                    const std::string& cat) {
  auto key = [&](std::size_t i) { return kColumns[i] + " (category " + cat + ")"; };
  EoSurface s;
  s.name = c[1];
  s.emissivity_lwir = fraction(c[2], path, key(2));
  s.emissivity_mwir = fraction(c[3], path, key(3));
  s.albedo = fraction(c[4], path, key(4));
  s.thermal_inertia = number(c[5], path, key(5));
  if (!(s.thermal_inertia > 0))
    throw InputError(path, key(5), "expected a positive thermal inertia, got " + c[5]);
  for (std::size_t k = 0; k < 4; ++k) s.reflectance[k] = fraction(c[6 + k], path, key(6 + k));
  return s;
}

}  // namespace

const EoSurface& EoSurfaceTable::at(std::int32_t category) const {
  const auto it = by_category.find(category);
  if (it == by_category.end()) {
    throw InputError(path, "id", "no row for category " + std::to_string(category));
  }
  return it->second;
}

double band_property(const EoSurface& s, EoBand b) {
  switch (b) {
    case EoBand::mwir:
      return s.emissivity_mwir;
    case EoBand::lwir:
      return s.emissivity_lwir;
    default:
      return s.reflectance[static_cast<std::size_t>(b)];
  }
}

EoSurfaceTable parse_eo_surface_table(const std::string& text, const std::string& path) {
  EoSurfaceTable t;
  t.path = path;
  std::stringstream in(text);
  std::string line;
  bool header = false;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.find_first_not_of(" \t\r") == std::string::npos)
      continue;
    const std::vector<std::string> c = split_csv(line);
    if (!header) {
      if (c != kColumns)
        throw InputError(path, "header",
                         "expected the columns id,name,emissivity_lwir,...,rho_nir");
      header = true;
      continue;
    }
    if (c.size() != kColumns.size()) {
      throw InputError(path, "row '" + line + "'",
                       "expected " + std::to_string(kColumns.size()) + " columns");
    }
    const auto id = static_cast<std::int32_t>(number(c[0], path, "id"));
    if (!t.by_category.emplace(id, parse_row(c, path, c[0])).second) {
      throw InputError(path, "id", "category " + c[0] + " appears twice");
    }
  }
  if (!header) throw InputError(path, "header", "no header line");
  return t;
}

EoSurfaceTable load_eo_surface_table(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw InputError(path, "", "cannot open the surface table");
  std::stringstream ss;
  ss << f.rdbuf();
  return parse_eo_surface_table(ss.str(), path);
}

std::string default_eo_surface_table(const std::string& scene_path) {
  return eo_surface_table_for_library(scene_backscatter_library(scene_path));
}

std::string eo_surface_table_for_library(const std::string& library_path) {
  const std::string library = library_path.empty() ? default_sigma0_library_path() : library_path;
  const std::filesystem::path named =
      data_dir() / "sensors_eo" / (std::filesystem::path(library).stem().string() + "-eo.csv");
  if (path_exists(named)) return named.string();
  return (data_dir() / "sensors_eo" / "generic-terrain-eo.csv").string();
}

}  // namespace ris
