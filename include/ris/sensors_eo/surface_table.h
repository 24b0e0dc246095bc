// Per-category optical and thermal surface properties (emissivity, albedo,
// thermal inertia, band reflectances), read from a CSV table such as
// data/sensors_eo/generic-terrain-eo.csv (whose header says where each
// number comes from). docs/sensors.md, "Surface table".
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>

#include "ris/sensors_eo/eo_band.h"

namespace ris {

struct EoSurface {
  std::string name;
  double emissivity_lwir = 1;
  double emissivity_mwir = 1;
  double albedo = 0;
  double thermal_inertia = 1000;        // J m^-2 K^-1 s^-1/2
  std::array<double, 4> reflectance{};  // blue, green, red, nir
};

struct EoSurfaceTable {
  std::string path;
  std::map<std::int32_t, EoSurface> by_category;

  // Throws InputError naming the table and the category for a category the
  // table lacks.
  const EoSurface& at(std::int32_t category) const;
};

// Reflectance (optical) or emissivity (thermal) of a surface in a band.
double band_property(const EoSurface& s, EoBand b);

// Parses the CSV (lines starting with '#' are comments; the first other line
// is the header with the columns id,name,emissivity_lwir,emissivity_mwir,
// albedo,thermal_inertia,rho_blue,rho_green,rho_red,rho_nir). Throws
// InputError naming the file, "<column> (category <id>)" and the expected
// range: emissivity, albedo and reflectance in [0, 1], thermal inertia > 0.
EoSurfaceTable parse_eo_surface_table(const std::string& text, const std::string& path);
EoSurfaceTable load_eo_surface_table(const std::string& path);

// The surface table for a scene when none is given: the one named after the
// scene's backscatter library, <data>/sensors_eo/<library stem>-eo.csv (the
// library the scene raster names, else the standard library ku-geometric),
// when it exists; else <data>/sensors_eo/generic-terrain-eo.csv.
std::string default_eo_surface_table(const std::string& scene_path);
// The same for a backscatter library's path or file name ("" the standard).
std::string eo_surface_table_for_library(const std::string& library);

}  // namespace ris
