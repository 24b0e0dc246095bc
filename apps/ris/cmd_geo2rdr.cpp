// `ris geo2rdr` and `ris rdr2geo`: the zero-Doppler geometry of an
// acquisition at chosen points (ris/geometry/zero_doppler.h).
//
//   ris geo2rdr -a winnipeg.h5 --point 49.45,-97.77,240
//   ris rdr2geo -a winnipeg.h5 --dem winnipeg_dem.tif --pixel 125,125
//
// Points come from --point/--pixel (repeatable) or a CSV file (--csv: lines
// "lat,lon,height" or "line,bin"; '#' starts a comment). The output is CSV
// on standard output, one row per point, with a header. Each point is checked
// before any work: a latitude in [-90, 90], a longitude in [-180, 360], a
// height in [-12, 100] km, a line or bin finite and within 10^7 of the grid
// (ris/sensor/product_values.h); the error names the option or CSV line.
#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acquisition_options.h"
#include "command_registry.h"
#include "ris/geometry/zero_doppler.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/io/safe_paths.h"
#include "ris/sensor/product_values.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris::app {
namespace {

struct PointArgs {
  AcquisitionArgs acq;
  std::vector<std::string> points;
  std::string csv;
  std::string dem;
  double height_m = std::nan("");
};

// Numbers separated by commas; `what` names the expected form in errors.
std::vector<double> numbers(const std::string& text, std::size_t n, const std::string& file,
                            const std::string& key, const std::string& what) {
  std::vector<double> v;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    try {
      std::size_t used = 0;
      v.push_back(std::stod(item, &used));
      while (used < item.size() && std::isspace(static_cast<unsigned char>(item[used]))) ++used;
      if (used != item.size()) throw std::invalid_argument(item);
    } catch (const std::exception&) {
      throw InputError(file, key, fmt::format("expected {}, got '{}'", what, text));
    }
  }
  if (v.size() != n) throw InputError(file, key, fmt::format("expected {}, got '{}'", what, text));
  return v;
}

// Checks one point's values; file and key name where it came from.
using PointCheck = void (*)(const std::vector<double>& v, const std::string& file,
                            const std::string& key);

// lat, lon, height: finite and on the Earth (ris/sensor/product_values.h).
void check_ground_point(const std::vector<double>& v, const std::string& file,
                        const std::string& key) {
  require_in_range(v[0], kLatitudeRange, file, key);
  require_in_range(v[1], kLongitudeRange, file, key);
  require_in_range(v[2], kGroundHeightRange, file, key);
}

// line, bin: finite and within the largest grid's size of it (a time or
// range computed from them stays finite).
void check_radar_pixel(const std::vector<double>& v, const std::string& file,
                       const std::string& key) {
  constexpr auto kMax = static_cast<double>(kMaxGridLines);
  const ValueRange r{-kMax, 2.0 * kMax, "", "a line or bin"};
  require_in_range(v[0], r, file, key);
  require_in_range(v[1], r, file, key);
}

std::vector<std::vector<double>> read_points(const PointArgs& a, std::size_t n,
                                             const std::string& option, const std::string& what,
                                             PointCheck check) {
  std::vector<std::vector<double>> out;
  for (const std::string& p : a.points) {
    out.push_back(numbers(p, n, "", option, what));
    check(out.back(), "", option);
  }
  if (!a.csv.empty()) {
    require_regular_input(a.csv, "--csv");
    std::ifstream f(a.csv);
    if (!f) throw InputError(a.csv, "--csv", "cannot open the file");
    std::string line;
    int no = 0;
    while (std::getline(f, line)) {
      ++no;
      const auto hash = line.find('#');
      if (hash != std::string::npos) line.resize(hash);
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const std::string key = fmt::format("line {}", no);
      out.push_back(numbers(line, n, a.csv, key, what));
      check(out.back(), a.csv, key);
    }
  }
  if (out.empty()) throw InputError("", option, "no points: give " + option + " or --csv");
  return out;
}

void print_header(const Acquisition& acq) {
  fmt::print("# {} ({}), {} lines x {} bins, look {}, orbit epoch {}\n", acq.source, acq.mission,
             acq.grid.lines, acq.grid.bins, acq.grid.look_side == LookSide::left ? "left" : "right",
             acq.orbit.epoch().iso());
  for (const std::string& n : acq.notes) fmt::print("# {}\n", n);
}

void print_row(const Acquisition& acq, const Geodetic& g, const RadarPoint& p, bool converged) {
  const RadarGrid& grid = acq.grid;
  const LookAngles a = look_angles(acq.ellipsoid, p.sensor_m, acq.ellipsoid.to_ecef(g));
  UtcTime utc = acq.orbit.epoch();
  utc.seconds_of_day += p.time_s;
  const double days = std::floor(utc.seconds_of_day / 86400.0);
  utc.days += static_cast<std::int64_t>(days);
  utc.seconds_of_day -= days * 86400.0;
  fmt::print("{:.9f},{:.9f},{:.4f},{},{:.9f},{:.4f},{:.4f},{:.4f},{:.6f},{:.6f},{:.6f},{:.3e},{}\n",
             rad_to_deg(g.lat_rad), rad_to_deg(g.lon_rad), g.height_m, utc.iso(), p.time_s,
             p.slant_range_m, grid.line_of_time(p.time_s), grid.bin_of_range(p.slant_range_m),
             a.incidence_deg, a.incidence_geocentric_deg, a.look_deg,
             doppler_hz(acq.orbit, acq.ellipsoid.to_ecef(g), p.time_s, grid.wavelength_m),
             converged ? "ok" : "outside-orbit");
}

constexpr const char* kColumns =
    "lat_deg,lon_deg,height_m,zero_doppler_utc,zero_doppler_time_s,slant_range_m,line,pixel,"
    "incidence_deg,incidence_geocentric_deg,look_deg,doppler_hz,status";

void run_geo2rdr(const PointArgs& a) {
  const auto pts =
      read_points(a, 3, "--point", "lat,lon,height (degrees, degrees, metres)", check_ground_point);
  const Acquisition acq = read_acquisition(a.acq.path, a.acq.options());
  print_header(acq);
  fmt::print("{}\n", kColumns);
  const double t_mid = 0.5 * (acq.grid.sensing_start_s + acq.grid.end_s());
  for (const auto& v : pts) {
    const Geodetic g{deg_to_rad(v[0]), deg_to_rad(v[1]), v[2]};
    const RadarPoint p = geo2rdr(acq.orbit, acq.ellipsoid.to_ecef(g), t_mid);
    print_row(acq, g, p, p.converged);
  }
}

void run_rdr2geo(const PointArgs& a) {
  const Acquisition acq = read_acquisition(a.acq.path, a.acq.options());
  if (a.dem.empty() == std::isnan(a.height_m)) {
    throw InputError("", "--dem", "give exactly one of --dem and --height");
  }
  if (a.dem.empty()) require_in_range(a.height_m, kGroundHeightRange, "", "--height");
  EllipsoidalDem dem;
  if (!a.dem.empty()) dem = read_ellipsoidal_dem(a.dem);
  const auto pts = read_points(a, 2, "--pixel", "line,bin (may be fractional)", check_radar_pixel);
  print_header(acq);
  if (!a.dem.empty()) fmt::print("# DEM {}: {}\n", a.dem, dem.vertical_note);
  fmt::print("{}\n", kColumns);
  const double h0 = a.dem.empty() ? a.height_m : dem.mean_height_m();
  for (const auto& v : pts) {
    const double t = acq.grid.time_of_line(v[0]);
    const double r = acq.grid.range_of_bin(v[1]);
    const ZeroDopplerFrame f(acq.orbit.interpolate(t), acq.grid.look_side, acq.ellipsoid);
    const GroundPoint gp =
        a.dem.empty() ? rdr2geo(
                            f, acq.ellipsoid, r, [&](double, double) { return a.height_m; }, h0)
                      : rdr2geo(
                            f, acq.ellipsoid, r,
                            [&](double la, double lo) { return dem.height_at(la, lo); }, h0);
    RadarPoint p;
    p.time_s = t;
    p.slant_range_m = r;
    p.sensor_m = f.sensor_m;
    if (!gp.converged) {
      fmt::print("nan,nan,nan,,{:.9f},{:.4f},{},{},nan,nan,nan,nan,off-dem\n", t, r, v[0], v[1]);
      continue;
    }
    print_row(acq, gp.geodetic, p, acq.orbit.covers(t));
  }
}

void add_geo2rdr(CLI::App& app) {
  auto a = std::make_shared<PointArgs>();
  auto* cmd = app.add_subcommand(
      "geo2rdr", "Zero-Doppler time, slant range, line, pixel and angles of ground points");
  add_acquisition_options(cmd, a->acq);
  cmd->add_option("--point,-p", a->points, "lat,lon,height (deg, deg, m above the ellipsoid)");
  cmd->add_option("--csv", a->csv, "CSV file of lat,lon,height lines");
  cmd->callback([a] { run_geo2rdr(*a); });
}

void add_rdr2geo(CLI::App& app) {
  auto a = std::make_shared<PointArgs>();
  auto* cmd = app.add_subcommand("rdr2geo",
                                 "Ground point (on a DEM or at a height) of radar lines and bins");
  add_acquisition_options(cmd, a->acq);
  cmd->add_option("--pixel", a->points, "line,bin of the acquisition's grid (may be fractional)");
  cmd->add_option("--csv", a->csv, "CSV file of line,bin lines");
  cmd->add_option("--dem", a->dem, "DEM (geographic WGS 84; geoid heights converted)");
  cmd->add_option("--height", a->height_m, "Constant height above the ellipsoid instead, m");
  cmd->callback([a] { run_rdr2geo(*a); });
}

const Registration reg_geo2rdr{"geo2rdr", add_geo2rdr};
const Registration reg_rdr2geo{"rdr2geo", add_rdr2geo};

}  // namespace
}  // namespace ris::app
