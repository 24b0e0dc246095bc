#include "ris/sensors_eo/eo_sensor_config.h"

#include <array>
#include <cstdio>

#include "ris/io/config_table.h"
#include "ris/util/error.h"

namespace ris {
namespace {

constexpr std::array<std::pair<std::string_view, EoKind>, 2> kKinds{
    {{"optical", EoKind::optical}, {"thermal", EoKind::thermal}}};

UtcDateTime parse_when(const std::string& date, const std::string& time, const std::string& path) {
  UtcDateTime t;
  char tail = 0;
  if (std::sscanf(date.c_str(), "%d-%d-%d%c", &t.year, &t.month, &t.day, &tail) != 3 ||
      t.month < 1 || t.month > 12 || t.day < 1 || t.day > 31) {
    throw InputError(path, "date", "expected a UTC date YYYY-MM-DD, got '" + date + "'");
  }
  int h = 0, m = 0;
  double s = 0;
  if (std::sscanf(time.c_str(), "%d:%d:%lf%c", &h, &m, &s, &tail) != 3 || h < 0 || h > 23 ||
      m < 0 || m > 59 || s < 0 || s >= 61) {
    throw InputError(path, "time", "expected a UTC time HH:MM:SS, got '" + time + "'");
  }
  t.hour = h + m / 60.0 + s / 3600.0;
  return t;
}

double fraction(ConfigTable& t, const std::string& key, double fallback) {
  const double v = t.get_double_or(key, fallback);
  if (!(v >= 0 && v <= 1)) {
    throw InputError(t.file(), t.key_path(key),
                     "expected a value in [0, 1], got " + std::to_string(v));
  }
  return v;
}

EoSensorConfig eo_sensor_from_table(const toml::table& doc, const std::string& path) {
  ConfigTable t(doc, path, "");
  EoSensorConfig c;
  c.path = path;
  c.kind = t.get_registered_enum<EoKind>("kind", kKinds);
  c.when = parse_when(t.get_string("date"), t.get_string("time"), path);
  const toml::node* bands = t.raw("bands");
  const toml::array* arr = bands ? bands->as_array() : nullptr;
  if (!arr || arr->empty())
    throw InputError(path, "bands", "expected a non-empty array of band names");
  for (const toml::node& n : *arr) {
    const auto name = n.value<std::string>();
    if (!name) throw InputError(path, "bands", "expected band names (strings)");
    const EoBand b = parse_eo_band(*name, path, "bands");
    if (eo_band_info(b).thermal != (c.kind == EoKind::thermal)) {
      throw InputError(path, "bands",
                       "band '" + *name + "' is " +
                           (eo_band_info(b).thermal ? "thermal" : "optical") + " but kind is " +
                           (c.kind == EoKind::thermal ? "thermal" : "optical"));
    }
    c.bands.push_back(b);
  }
  c.noise = t.get_double_or("noise", 0.0);
  if (!(c.noise >= 0)) throw InputError(path, "noise", "expected a non-negative noise sigma");
  c.seed = static_cast<std::uint64_t>(t.get_int_or("seed", 1));
  if (t.has("latitude")) c.latitude_deg = t.get_double("latitude");
  if (t.has("longitude")) c.longitude_deg = t.get_double("longitude");
  if (c.latitude_deg && (*c.latitude_deg < -90 || *c.latitude_deg > 90)) {
    throw InputError(path, "latitude", "expected degrees in [-90, 90]");
  }
  if (auto a = t.subtable("atmosphere")) {
    c.transmittance = fraction(*a, "transmittance", c.transmittance);
    c.sky_fraction = fraction(*a, "sky_fraction", c.sky_fraction);
    c.path_radiance = a->get_double_or("path_radiance", c.path_radiance);
    c.sky_temperature_k = a->get_double_or("sky_temperature", c.sky_temperature_k);
    a->finish();
  }
  if (auto th = t.subtable("thermal")) {
    c.mean_temperature_k = th->get_double_or("mean_temperature", c.mean_temperature_k);
    if (!(c.mean_temperature_k > 0)) {
      throw InputError(path, "thermal.mean_temperature", "expected a positive temperature in K");
    }
    th->finish();
  }
  t.finish();
  return c;
}

}  // namespace

EoSensorConfig parse_eo_sensor(const std::string& text, const std::string& path) {
  return eo_sensor_from_table(parse_toml_text(text, path), path);
}

EoSensorConfig load_eo_sensor(const std::string& path) {
  return eo_sensor_from_table(parse_toml_file(path), path);
}

}  // namespace ris
