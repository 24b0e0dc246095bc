#include "ris/sensors_eo/eo_sensor_config.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "ris/io/config_table.h"
#include "ris/sensors_eo/camera_view.h"
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

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

double angle_deg_in(ConfigTable& t, const std::string& key, double fallback_deg, double lo,
                    double hi) {
  const double v = t.get_quantity_or(key, Quantity::angle, fallback_deg / kDegPerRad) * kDegPerRad;
  if (!(v >= lo && v <= hi)) {
    t.fail(key, fmt::format("expected an angle in [{:g}, {:g}] deg, got {:g} deg", lo, hi, v));
  }
  return v;
}

int int_in(ConfigTable& t, const std::string& key, std::int64_t fallback, std::int64_t lo,
           std::int64_t hi) {
  const std::int64_t v = t.get_int_or(key, fallback);
  if (v < lo || v > hi) {
    t.fail(key, "expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                    "], got " + std::to_string(v));
  }
  return static_cast<int>(v);
}

double positive(ConfigTable& t, const std::string& key) {
  const double v = t.get_double(key);
  if (!(v > 0 && std::isfinite(v))) t.fail(key, "expected a positive number");
  return v;
}

FrameCamera parse_camera(ConfigTable& t) {
  FrameCamera cam;
  const std::vector<double> xy = t.get_quantity_array("position", Quantity::length);
  if (xy.size() != 2 || !std::isfinite(xy[0]) || !std::isfinite(xy[1])) {
    t.fail("position", "expected [x, y] in scene metres (2 finite values)");
  }
  cam.x_m = xy[0];
  cam.y_m = xy[1];
  cam.altitude_m = t.get_quantity("altitude", Quantity::length);
  if (!std::isfinite(cam.altitude_m)) t.fail("altitude", "expected a finite height");
  cam.heading_deg = angle_deg_in(t, "heading", 0.0, -360.0, 360.0);
  cam.depression_deg = angle_deg_in(t, "depression", 90.0, 0.0, 90.0);
  cam.fov_deg = angle_deg_in(t, "fov", 20.0, 0.01, 170.0);
  cam.cols = int_in(t, "columns", 512, 1, 16384);
  cam.rows = int_in(t, "rows", 512, 1, 16384);
  cam.samples = int_in(t, "samples", 2, 1, 8);
  cam.mtf_at_nyquist = t.get_double_or("mtf_at_nyquist", 1.0);
  if (!(cam.mtf_at_nyquist > 0 && cam.mtf_at_nyquist <= 1)) {
    t.fail("mtf_at_nyquist", "expected the MTF at Nyquist in (0, 1] (1: no blur)");
  }
  const std::int64_t rays = camera_ray_count(cam);
  if (rays > kMaxCameraRays) {
    t.fail("samples",
           "columns x rows x samples^2 (+ 1 centre ray if even) = " + std::to_string(rays) +
               " rays, more than " + std::to_string(kMaxCameraRays) + ": fewer pixels or samples");
  }
  t.finish();
  return cam;
}

Detector parse_detector(ConfigTable& t) {
  Detector d;
  d.electrons_per_radiance = positive(t, "electrons_per_radiance");
  d.read_noise_e = t.get_double_or("read_noise", 0.0);
  if (!(d.read_noise_e >= 0 && std::isfinite(d.read_noise_e))) {
    t.fail("read_noise", "expected electrons rms >= 0");
  }
  d.full_well_e = positive(t, "full_well");
  d.bits = int_in(t, "bits", 12, 1, 16);
  t.finish();
  return d;
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
    if (std::find(c.bands.begin(), c.bands.end(), b) != c.bands.end()) {
      throw InputError(path, "bands", "band '" + *name + "' is named twice");
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
  if (auto cam = t.subtable("camera")) c.camera = parse_camera(*cam);
  if (auto det = t.subtable("detector")) {
    if (c.kind == EoKind::thermal) {
      det->fail("electrons_per_radiance",
                "a detector gives an optical camera's digital numbers; a thermal sensor's noise "
                "is its NETD (`noise`, K)");
    }
    c.detector = parse_detector(*det);
  }
  if (c.detector && !c.camera) {
    throw InputError(path, "detector", "a detector needs a [camera] table (the frame camera)");
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
