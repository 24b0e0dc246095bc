// Materials of cultural objects: a perfect conductor or a dielectric given
// by its complex relative permittivity (eps' - j eps'') as a function of
// frequency, plus an rms surface roughness. Shipped in
// data/materials/materials.toml (each row with its citation; docs/objects.md).
//
// Example:
//   auto lib = ris::MaterialLibrary::load(ris::default_materials_path());
//   std::complex<double> eps = lib.find("concrete").permittivity(9.6e9);
#pragma once

#include <complex>
#include <string>
#include <vector>

namespace ris {

enum class MaterialKind { pec, itu_p2040, constant, water_debye };

struct Material {
  std::string name;
  MaterialKind kind = MaterialKind::pec;
  double a = 1.0, b = 0.0, c = 0.0, d = 0.0;  // itu-p2040: eps' = a f^b, sigma = c f^d
  double eps_re = 1.0, eps_im = 0.0;          // constant
  double temperature_c = 20.0;                // water-debye
  double f_min_hz = 0.0, f_max_hz = 0.0;      // validity (not for pec)
  double rms_height_m = 0.0;
  std::string citation;
  std::string file;  // where it was read, for messages

  bool is_pec() const { return kind == MaterialKind::pec; }
  // eps' - j eps''; InputError (file, material.<name>) outside the row's
  // frequency validity. Not for pec.
  std::complex<double> permittivity(double frequency_hz) const;
};

// ITU-R P.2040-1 eq. (9): eps'' = sigma / (2 pi f eps0) = 17.98 sigma / f_GHz.
std::complex<double> itu_p2040_permittivity(double a, double b, double c, double d,
                                            double frequency_hz);
// Pure water, single Debye (Stogryn 1971 fits, eps_inf = 4.9).
std::complex<double> water_debye_permittivity(double temperature_c, double frequency_hz);

class MaterialLibrary {
 public:
  // Strict: unknown keys, a missing key, eps'' < 0, an empty or inverted
  // validity are InputError naming the file, the material and the key.
  static MaterialLibrary load(const std::string& path);

  // InputError naming the library and the known names when absent.
  const Material& find(const std::string& name) const;
  const std::vector<Material>& materials() const { return materials_; }

 private:
  std::string path_;
  std::vector<Material> materials_;
};

// data/materials/materials.toml of the data folder.
std::string default_materials_path();

}  // namespace ris
