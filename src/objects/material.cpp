#include "ris/objects/material.h"

#include <cmath>

#include <fmt/format.h>

#include "ris/io/config_table.h"
#include "ris/io/safe_paths.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

constexpr double kEps0 = 8.854187817e-12;  // F/m

Material read_material(ConfigTable& t, const std::string& name, const std::string& file) {
  Material m;
  m.name = name;
  m.file = file;
  m.kind = t.get_enum<MaterialKind>("kind", {{"pec", MaterialKind::pec},
                                             {"itu-p2040", MaterialKind::itu_p2040},
                                             {"constant", MaterialKind::constant},
                                             {"water-debye", MaterialKind::water_debye}});
  m.rms_height_m = t.get_double("rms_height_m");
  if (!(m.rms_height_m >= 0.0) || !std::isfinite(m.rms_height_m)) {
    t.fail("rms_height_m", fmt::format("expected a finite height >= 0 m, got {}", m.rms_height_m));
  }
  m.citation = t.get_string("citation");
  if (m.kind == MaterialKind::itu_p2040) {
    m.a = t.get_double("a");
    m.b = t.get_double("b");
    m.c = t.get_double("c");
    m.d = t.get_double("d");
    if (!(m.a >= 1.0)) t.fail("a", fmt::format("expected eps' = a f^b with a >= 1, got {}", m.a));
    if (!(m.c >= 0.0)) {
      t.fail("c",
             fmt::format("expected a conductivity coefficient >= 0 (eps'' >= 0), got {}", m.c));
    }
  } else if (m.kind == MaterialKind::constant) {
    m.eps_re = t.get_double("eps_re");
    m.eps_im = t.get_double("eps_im");
    if (!(m.eps_im >= 0.0)) {
      t.fail("eps_im", fmt::format("expected eps'' >= 0 (a passive medium), got {}", m.eps_im));
    }
    if (!(m.eps_re >= 1.0)) t.fail("eps_re", fmt::format("expected eps' >= 1, got {}", m.eps_re));
  } else if (m.kind == MaterialKind::water_debye) {
    m.temperature_c = t.get_double("temperature_c");
    if (!(m.temperature_c >= 0.0 && m.temperature_c <= 40.0)) {
      t.fail("temperature_c",
             fmt::format("expected 0..40 C (the Stogryn fits' range), got {}", m.temperature_c));
    }
  }
  if (m.kind != MaterialKind::pec) {
    m.f_min_hz = t.get_double("f_min_ghz") * 1e9;
    m.f_max_hz = t.get_double("f_max_ghz") * 1e9;
    if (!(m.f_min_hz > 0.0 && m.f_max_hz > m.f_min_hz)) {
      t.fail("f_max_ghz", "expected 0 < f_min_ghz < f_max_ghz");
    }
  }
  t.finish();
  return m;
}

}  // namespace

std::complex<double> itu_p2040_permittivity(double a, double b, double c, double d,
                                            double frequency_hz) {
  const double f_ghz = frequency_hz * 1e-9;
  const double eps_re = a * std::pow(f_ghz, b);
  const double sigma = c * std::pow(f_ghz, d);
  return {eps_re, -sigma / (2.0 * kPi * kEps0 * frequency_hz)};
}

std::complex<double> water_debye_permittivity(double temperature_c, double frequency_hz) {
  const double t = temperature_c;
  constexpr double kEpsWInf = 4.9;
  const double eps_w0 = 88.045 - 0.4147 * t + 6.295e-4 * t * t + 1.075e-5 * t * t * t;
  const double two_pi_tau = 1.1109e-10 - 3.824e-12 * t + 6.938e-14 * t * t - 5.096e-16 * t * t * t;
  const double ft = frequency_hz * two_pi_tau;
  const double re = kEpsWInf + (eps_w0 - kEpsWInf) / (1.0 + ft * ft);
  const double im = ft * (eps_w0 - kEpsWInf) / (1.0 + ft * ft);
  return {re, -im};
}

std::complex<double> Material::permittivity(double frequency_hz) const {
  if (kind == MaterialKind::pec) {
    throw InputError(file, "material." + name, "a perfect conductor has no permittivity");
  }
  if (!(frequency_hz >= f_min_hz && frequency_hz <= f_max_hz)) {
    throw InputError(file, "material." + name + ".f_min_ghz",
                     fmt::format("{} GHz is outside the row's validity {} .. {} GHz ({}); use "
                                 "another material or widen the row with a source",
                                 frequency_hz * 1e-9, f_min_hz * 1e-9, f_max_hz * 1e-9, citation));
  }
  switch (kind) {
    case MaterialKind::itu_p2040:
      return itu_p2040_permittivity(a, b, c, d, frequency_hz);
    case MaterialKind::constant:
      return {eps_re, -eps_im};
    case MaterialKind::water_debye:
      return water_debye_permittivity(temperature_c, frequency_hz);
    case MaterialKind::pec:
      break;
  }
  return {1.0, 0.0};
}

MaterialLibrary MaterialLibrary::load(const std::string& path) {
  require_regular_input(path);
  const toml::table doc = parse_toml_file(path);
  ConfigTable root(doc, path, "");
  MaterialLibrary lib;
  lib.path_ = path;
  auto materials = root.subtable("material");
  if (!materials) root.fail("material", "expected [material.<name>] tables");
  for (const std::string& name : materials->keys()) {
    auto t = materials->subtable(name);
    if (!t) materials->fail(name, "expected a table [material." + name + "]");
    lib.materials_.push_back(read_material(*t, name, path));
  }
  materials->finish();
  root.finish();
  if (lib.materials_.empty()) root.fail("material", "no material defined");
  return lib;
}

const Material& MaterialLibrary::find(const std::string& name) const {
  std::string known;
  for (const Material& m : materials_) {
    if (m.name == name) return m;
    known += (known.empty() ? "" : ", ") + m.name;
  }
  throw InputError(path_, "material." + name, "no such material; the library has " + known);
}

std::string default_materials_path() {
  return (data_dir() / "materials" / "materials.toml").string();
}

}  // namespace ris
