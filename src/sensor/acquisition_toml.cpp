// ris's own acquisition file (TOML; docs/geometry.md, data/acquisitions/):
//
//   [acquisition]
//   mission = "example"                  # optional, free text
//   epoch = "2024-06-01T10:00:00"        # UTC; every time below is seconds since it
//   look_side = "right"                  # or "left"
//   frequency = "5.405 GHz"              # or wavelength = "5.55 cm"
//   polarisation = "VV"                  # optional
//   [grid]
//   first_line_time = "0 s"              # zero-Doppler time of line 0
//   line_interval = "10 ms"
//   lines = 1000
//   near_range = "795 km"
//   range_spacing = "76 m"
//   bins = 2000
//   prf = "1700 Hz"                      # optional (default 1 / line_interval)
//   [orbit]
//   kind = "circular"                    # "state_vectors", "circular" or "flight_line"
//   ...                                  # the kind's keys, below
#include <fmt/format.h>

#include <string>
#include <vector>

#include "ris/io/config_table.h"
#include "ris/sensor/acquisition.h"
#include "ris/sensor/generated_orbit.h"
#include "ris/util/error.h"
#include "ris/util/path_exists.h"
#include "ris/util/units.h"

namespace ris {
namespace {

Vec3 vec3_of(ConfigTable& t, const std::string& key) {
  const auto v = t.get_double_array(key);
  if (v.size() != 3) t.fail(key, fmt::format("expected [x, y, z], got {} numbers", v.size()));
  return {v[0], v[1], v[2]};
}

double positive(ConfigTable& t, const std::string& key, Quantity q) {
  const double v = t.get_quantity(key, q);
  if (!(v > 0.0)) t.fail(key, "expected a value > 0");
  return v;
}

}  // namespace

Acquisition read_acquisition_toml(const std::filesystem::path& path) {
  const std::string file = path.string();
  const toml::table doc = parse_toml_file(file);
  ConfigTable root(doc, file, "");
  Acquisition acq;
  acq.source = file;
  acq.format = "ris-toml";

  auto head = root.subtable("acquisition");
  if (!head) root.fail("acquisition", "missing required table");
  acq.mission = head->get_string_or("mission", "ris");
  acq.polarisation = head->get_string_or("polarisation", "");
  const std::string epoch_text = head->get_string("epoch");
  const auto epoch = parse_utc(epoch_text);
  if (!epoch) head->fail("epoch", "expected a UTC date-time \"YYYY-MM-DDTHH:MM:SS[.ffffff]\"");
  RadarGrid& g = acq.grid;
  // Without regard to case, as every enum value (ConfigTable::get_enum).
  g.look_side =
      head->get_enum<LookSide>("look_side", {{"left", LookSide::left}, {"right", LookSide::right}});
  if (head->has("frequency") == head->has("wavelength")) {
    head->fail("frequency", "give exactly one of frequency and wavelength");
  }
  g.wavelength_m = head->has("frequency")
                       ? kSpeedOfLight_m_per_s / positive(*head, "frequency", Quantity::frequency)
                       : positive(*head, "wavelength", Quantity::length);
  head->finish();

  auto grid = root.subtable("grid");
  if (!grid) root.fail("grid", "missing required table");
  g.sensing_start_s = grid->get_quantity("first_line_time", Quantity::time);
  g.line_interval_s = positive(*grid, "line_interval", Quantity::time);
  g.near_range_m = positive(*grid, "near_range", Quantity::length);
  g.range_spacing_m = positive(*grid, "range_spacing", Quantity::length);
  const auto lines = grid->get_int("lines"), bins = grid->get_int("bins");
  if (lines < 1 || lines > 10'000'000) grid->fail("lines", "expected 1..10000000");
  if (bins < 1 || bins > 10'000'000) grid->fail("bins", "expected 1..10000000");
  g.lines = static_cast<int>(lines);
  g.bins = static_cast<int>(bins);
  g.prf_hz = grid->get_quantity_or("prf", Quantity::frequency, 1.0 / g.line_interval_s);
  grid->finish();

  auto orbit = root.subtable("orbit");
  if (!orbit) root.fail("orbit", "missing required table");
  enum class OrbitKind { state_vectors, circular, flight_line };
  const OrbitKind kind =
      orbit->get_enum<OrbitKind>("kind", {{"state_vectors", OrbitKind::state_vectors},
                                          {"circular", OrbitKind::circular},
                                          {"flight_line", OrbitKind::flight_line}});
  // Generated orbits cover the grid with a margin for points off its ends.
  const double t0 = g.sensing_start_s, t1 = g.end_s();
  if (kind == OrbitKind::state_vectors) {
    std::vector<StateVector> sv;
    for (ConfigTable& s : orbit->table_array("state_vector")) {
      sv.push_back(
          {s.get_quantity("time", Quantity::time), vec3_of(s, "position"), vec3_of(s, "velocity")});
      s.finish();
    }
    acq.orbit = Orbit(*epoch, std::move(sv), file);
  } else if (kind == OrbitKind::circular) {
    CircularOrbitParams p;
    p.altitude_m = positive(*orbit, "altitude", Quantity::length);
    p.inclination_rad = orbit->get_quantity("inclination", Quantity::angle);
    p.ascending_node_lon_rad = orbit->get_quantity("ascending_node_longitude", Quantity::angle);
    p.argument_of_latitude_rad =
        orbit->get_quantity_or("argument_of_latitude", Quantity::angle, 0.0);
    acq.orbit = make_circular_orbit(p, acq.ellipsoid, *epoch, t0 - 60.0, t1 + 60.0, 10.0);
  } else {
    FlightLineParams p;
    p.lat_rad = orbit->get_quantity("latitude", Quantity::angle);
    p.lon_rad = orbit->get_quantity("longitude", Quantity::angle);
    p.height_m = positive(*orbit, "height", Quantity::length);
    p.heading_rad = orbit->get_quantity("heading", Quantity::angle);
    p.speed_m_s = positive(*orbit, "speed", Quantity::speed);
    acq.orbit = make_flight_line_orbit(p, acq.ellipsoid, *epoch, t0 - 30.0, t1 + 30.0, 1.0);
  }
  orbit->finish();
  root.finish();
  if (!acq.orbit.covers(t0) || !acq.orbit.covers(t1)) {
    throw InputError(file, "orbit", "the state vectors do not cover the grid's lines");
  }
  return acq;
}

Acquisition read_acquisition(const std::filesystem::path& path, const AcquisitionOptions& options) {
  if (!path_exists(path)) {
    throw InputError(path.string(), "", "no such file or folder");
  }
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".h5" || ext == ".hdf5" || ext == ".he5") return read_nisar_rslc(path, options);
  if (ext == ".safe" || ext == ".xml") return read_sentinel1(path, options);
  if (ext == ".toml") return read_acquisition_toml(path);
  throw InputError(path.string(), "",
                   "unknown acquisition format: expected a NISAR RSLC (.h5), a Sentinel-1 "
                   ".SAFE folder or annotation .xml, or a ris acquisition .toml");
}

}  // namespace ris
