// `ris topo --acquisition P --dem D --out DIR`: radar-geometry layers on an
// acquisition's own grid, like ISCE's topo (ris/geometry/topo.h,
// docs/geometry.md). One GeoTIFF per layer, in radar geometry (rows = lines,
// columns = bins of the window), each with its band description, no-data
// and the acquisition's grid in its metadata; plus quick-look PNGs of the
// incidence and the simulated amplitude. Prints the DEM pass's throughput
// (geo2rdr facets per second).
#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "acquisition_options.h"
#include "command_registry.h"
#include "ris/geometry/topo.h"
#include "ris/io/atomic_file.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/io/raster_io.h"
#include "ris/util/error.h"
#include "ris/util/resource_guard.h"

namespace ris::app {
namespace {

struct TopoArgs {
  AcquisitionArgs acq;
  std::string dem;
  std::string out;
  int oversample = 0;
  int threads = 0;
  bool full_grid = false;
  bool quiet = false;
};

// A grey quick look: values between the 1st and 99th percentiles.
std::vector<std::uint8_t> quicklook(const std::vector<float>& v) {
  std::vector<float> sorted;
  for (float x : v) {
    if (std::isfinite(x)) sorted.push_back(x);
  }
  std::vector<std::uint8_t> out(v.size(), 0);
  if (sorted.empty()) return out;
  std::sort(sorted.begin(), sorted.end());
  const float lo = sorted[sorted.size() / 100], hi = sorted[sorted.size() * 99 / 100];
  const float span = hi > lo ? hi - lo : 1.0F;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!std::isfinite(v[i])) continue;
    out[i] = static_cast<std::uint8_t>(std::clamp((v[i] - lo) / span, 0.0F, 1.0F) * 254.0F + 1.0F);
  }
  return out;
}

void run_topo(const TopoArgs& a) {
  checked_thread_count(a.threads, "--threads");  // the cap (ris/util/resource_guard.h)
  const Acquisition acq = read_acquisition(a.acq.path, a.acq.options());
  const EllipsoidalDem dem = read_ellipsoidal_dem(a.dem);
  if (a.oversample < 0 || a.oversample > 64) {
    throw InputError("", "--oversample", "expected 0 (automatic) to 64");
  }
  TopoOptions opt;
  opt.oversample = a.oversample;
  opt.full_grid = a.full_grid;
  opt.threads = a.threads;
  const TopoLayers t = compute_topo(acq, dem, opt);
  const GridWindow& w = t.window;
  const RadarGrid& g = acq.grid;

  RasterMetadata md;
  md["RIS_ACQUISITION"] = acq.source;
  md["RIS_ACQUISITION_FORMAT"] = acq.format;
  md["RIS_MISSION"] = acq.mission;
  md["RIS_DEM"] = a.dem;
  md["RIS_DEM_VERTICAL"] = dem.vertical_note;
  md["RIS_GEOMETRY"] = "radar (rows: zero-Doppler lines, columns: slant-range bins)";
  md["RIS_WINDOW_FIRST_LINE"] = std::to_string(w.line0);
  md["RIS_WINDOW_FIRST_BIN"] = std::to_string(w.bin0);
  md["RIS_GRID_LINES"] = std::to_string(g.lines);
  md["RIS_GRID_BINS"] = std::to_string(g.bins);
  md["RIS_ORBIT_EPOCH_UTC"] = acq.orbit.epoch().iso();
  md["RIS_FIRST_LINE_TIME_S"] = fmt::format("{:.9f}", g.time_of_line(w.line0));
  md["RIS_LINE_INTERVAL_S"] = fmt::format("{:.12g}", g.line_interval_s);
  md["RIS_NEAR_RANGE_M"] = fmt::format("{:.6f}", g.range_of_bin(w.bin0));
  md["RIS_RANGE_SPACING_M"] = fmt::format("{:.9g}", g.range_spacing_m);
  md["RIS_LOOK_SIDE"] = g.look_side == LookSide::left ? "left" : "right";
  md["RIS_WAVELENGTH_M"] = fmt::format("{:.9g}", g.wavelength_m);
  md["RIS_DEM_OVERSAMPLE"] = std::to_string(t.oversample);
  md["RIS_BETA_AREA_M2"] = fmt::format("{:.6g}", t.beta_area_m2);
  md["RIS_MASK_CODES"] = "0 none, 1 shadow, 2 layover, 3 both";

  StagedDirectory out(a.out);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const auto f32 = [&](const char* name, const std::vector<float>& v, const char* desc) {
    write_geotiff<float>(out.path(name), v.data(), w.bins, w.lines, nullptr, nan, md, desc);
  };
  write_geotiff<double>(out.path("lat.tif"), t.lat_deg.data(), w.bins, w.lines, nullptr, nan, md,
                        "latitude_deg (WGS 84)");
  write_geotiff<double>(out.path("lon.tif"), t.lon_deg.data(), w.bins, w.lines, nullptr, nan, md,
                        "longitude_deg (WGS 84)");
  f32("hgt.tif", t.height_m, "height_m above the WGS 84 ellipsoid");
  f32("incidence.tif", t.incidence_deg, "incidence_deg to the ellipsoid normal");
  f32("incidence_geocentric.tif", t.incidence_geocentric_deg,
      "incidence_geocentric_deg to the geocentric radius");
  f32("local_incidence.tif", t.local_incidence_deg, "local_incidence_deg to the DEM normal");
  f32("look.tif", t.look_deg, "look_deg at the sensor from its geodetic nadir");
  f32("heading.tif", t.heading_deg, "heading_deg of the platform, clockwise from north");
  f32("gamma_area.tif", t.gamma_area_m2,
      "gamma_area_m2 projected on the plane normal to the look direction (Small 2011)");
  f32("simamp.tif", t.simulated_amplitude, "simulated amplitude sqrt(beta0), Muhleman surface");
  write_geotiff<std::uint8_t>(out.path("layover_shadow_mask.tif"), t.mask.data(), w.bins, w.lines,
                              nullptr, std::nullopt, md,
                              "layover_shadow_mask: 0 none, 1 shadow, 2 layover, 3 both");
  write_png_gray(out.path("incidence.png"), quicklook(t.incidence_deg).data(), w.bins, w.lines);
  write_png_gray(out.path("simamp.png"), quicklook(t.simulated_amplitude).data(), w.bins, w.lines);
  out.commit();

  if (a.quiet) return;
  const int threads = a.threads > 0 ? a.threads : omp_get_max_threads();
  std::size_t shadow = 0, layover = 0;
  for (std::uint8_t m : t.mask) {
    shadow += (m & kMaskShadow) != 0;
    layover += (m & kMaskLayover) != 0;
  }
  fmt::print("{} ({}): window lines {}..{} x bins {}..{} of {} x {}\n", acq.source, acq.mission,
             w.line0, w.line0 + w.lines - 1, w.bin0, w.bin0 + w.bins - 1, g.lines, g.bins);
  for (const std::string& n : acq.notes) fmt::print("  {}\n", n);
  fmt::print("DEM {}: {}\n", a.dem, dem.vertical_note);
  fmt::print("radar pass: {} pixels in {:.3f} s ({} off the DEM); shadow {}, layover {}\n",
             w.size(), t.radar_seconds, t.unconverged, shadow, layover);
  fmt::print(
      "DEM pass: {} DEM cells x {}^2 facets = {} geo2rdr in {:.3f} s on {} threads: {:.1f} M "
      "facets/s ({:.1f} M per CPU-second)\n",
      t.dem_cells, t.oversample, t.dem_facets, t.dem_seconds, threads,
      static_cast<double>(t.dem_facets) / std::max(t.dem_seconds, 1e-9) / 1e6,
      static_cast<double>(t.dem_facets) / std::max(t.dem_cpu_seconds, 1e-9) / 1e6);
  fmt::print("wrote {}\n", a.out);
}

void add_topo(CLI::App& app) {
  auto a = std::make_shared<TopoArgs>();
  auto* cmd = app.add_subcommand(
      "topo", "Radar-geometry layers on an acquisition's grid (lat, lon, height, incidence, ...)");
  add_acquisition_options(cmd, a->acq);
  cmd->add_option("--dem", a->dem, "DEM (geographic WGS 84; geoid heights converted)")->required();
  cmd->add_option("--out,-o", a->out, "Output folder")->required();
  cmd->add_option("--oversample", a->oversample,
                  "DEM facets per cell side in the DEM pass (0: automatic)")
      ->capture_default_str();
  cmd->add_option("--threads", a->threads, "Threads (0: all)")->capture_default_str();
  cmd->add_flag("--full-grid", a->full_grid,
                "The whole radar grid, not only the window the DEM covers");
  cmd->add_flag("--quiet,-q", a->quiet, "Print nothing");
  cmd->callback([a] { run_topo(*a); });
}

const Registration reg{"topo", add_topo};

}  // namespace
}  // namespace ris::app
