#include "sim/modes/acquisition_setup.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ris/image/ground_range.h"
#include "ris/scene/geo_frame.h"
#include "ris/sim/slar_run_setup.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris::detail {

namespace {

// Speed of light (m/s), for the acquisition's frequency.
constexpr double kLightSpeed_m_s = 299792458.0;

// A grid for the set-up's checks (SAR resolution against the DEM's
// posting): the DEM's cell size in metres at its centre, no arrays.
Scene dem_grid(const EllipsoidalDem& dem, const Ellipsoid& e) {
  Scene grid;
  grid.rows = dem.all_rows();
  grid.cols = dem.all_cols();
  const double lat = dem.lat0_rad + 0.5 * (grid.rows - 1) * dem.dlat_rad;
  grid.dx_m = std::abs(dem.dlon_rad) * e.prime_vertical_radius_m(lat) * std::cos(lat);
  grid.dy_m = std::abs(dem.dlat_rad) * e.meridional_radius_m(lat);
  return grid;
}

}  // namespace

std::vector<std::uint16_t> categories_on_dem(const EllipsoidalDem& dem, const Scene& scene,
                                             const std::string& source, std::uint16_t fallback) {
  const GeoFrame frame(scene.crs_wkt, source);
  std::vector<std::uint16_t> out(dem.height_m.size(), fallback);
  for (int r = 0; r < dem.rows; ++r) {
    for (int c = 0; c < dem.cols; ++c) {
      const auto [x, y] =
          frame.scene_from_lonlat(rad_to_deg(dem.lon0_rad + (dem.col0 + c) * dem.dlon_rad),
                                  rad_to_deg(dem.lat0_rad + (dem.row0 + r) * dem.dlat_rad));
      const auto [col_f, row_f] = scene.grid_from_world(x, y);
      const int sr = static_cast<int>(std::floor(row_f)), sc = static_cast<int>(std::floor(col_f));
      if (!scene.contains(sr, sc) || scene.valid[scene.index(sr, sc)] == 0) continue;
      out[static_cast<std::size_t>(r) * static_cast<std::size_t>(dem.cols) +
          static_cast<std::size_t>(c)] = scene.category[scene.index(sr, sc)];
    }
  }
  return out;
}

std::vector<std::uint16_t> sorted_categories(std::vector<std::uint16_t> c) {
  std::sort(c.begin(), c.end());
  c.erase(std::unique(c.begin(), c.end()), c.end());
  return c;
}

void check_acquisition_radar(const RadarParams& radar, const AcquisitionSimOptions& options) {
  if (radar.mode == RadarMode::ppi) {
    throw InputError(radar.source_file, "mode",
                     "an acquisition's radar grid is a SLAR or SAR image; expected mode = \"slar\" "
                     "or \"sar\"");
  }
  if (radar.mode == RadarMode::sar && radar.sar.coherent) {
    throw InputError(radar.source_file, "sar.coherent",
                     "the coherent SAR is not run on an acquisition's grid yet; expected "
                     "coherent = false");
  }
  if (options.samples_per_bin < 1) {
    throw InputError("", "--samples-per-bin",
                     fmt::format("expected 1 or more, got {}", options.samples_per_bin));
  }
}

void set_up_acquisition(const Acquisition& acq, const EllipsoidalDem& dem, const RadarParams& radar,
                        const Sigma0Source& sigma0, const AcquisitionSimOptions& options,
                        const AcquisitionFrame& frame, AcquisitionSetup& s,
                        const std::vector<std::uint16_t>* categories_used) {
  const RadarGrid& g = acq.grid;
  const GridWindow& w = frame.window;
  AcquisitionSimulation& out = s.out;
  out.earth = options.earth;
  out.category = options.category;
  out.window = w;
  out.sensor_height_m = frame.sensor_height_m;
  out.ground_azimuth_spacing_m = frame.ground_azimuth_spacing_m;
  out.acquisition_source = acq.source;
  out.acquisition_format = acq.format;
  out.mission = acq.mission;
  out.polarisation = acq.polarisation;
  out.grid = g;
  out.acquisition_notes = acq.notes;
  out.dem_source = dem.source;
  out.dem_vertical_note = frame.dem_vertical_note;
  out.dem_min_m = frame.dem_min_m;
  out.dem_max_m = frame.dem_max_m;

  // The radar at the acquisition's wavelength.
  SlarSimulation& sim = out.sim;
  sim.radar = radar_at_band(radar, kLightSpeed_m_s / g.wavelength_m, radar.polarisation);
  sim.radar.earth = options.earth;
  sim.derived = derive(sim.radar);

  // The engine's layout: the window's lines, the profile's points as samples.
  s.run.emplace(AcquisitionRun{acq, dem, w, options.earth, options.category, nullptr,
                               frame.dem_min_m, frame.dem_max_m, options.samples_per_bin});
  AcquisitionRun& run = *s.run;
  std::vector<std::uint16_t> categories{options.category};
  if (options.land_cover != nullptr) {
    if (categories_used != nullptr) {  // the DEM read in windows later
      categories = *categories_used;
    } else {
      s.dem_category =
          categories_on_dem(dem, *options.land_cover, options.land_cover_source, options.category);
      categories = sorted_categories(s.dem_category);
      run.dem_category = s.dem_category.data();
    }
    out.land_cover_source = options.land_cover_source;
  }
  out.profile_points = acquisition_max_points(run);
  run.max_points = out.profile_points;
  SlarGeometry& layout = sim.geometry;
  layout.lines = w.lines;
  layout.samples = static_cast<int>(out.profile_points);
  layout.line_spacing_m = out.ground_azimuth_spacing_m;
  layout.altitude_m = out.sensor_height_m;
  layout.sample_step_m = 1.0;
  layout.first_sample_u_m = 1.0;  // no sample is "behind" the sensor
  run.layout = &layout;

  // Radiometry (the categories on the DEM), the grid's slant-range bins,
  // SAR windows and noise.
  const std::string backscatter_file =
      options.backscatter_file.empty() ? sigma0.description() : options.backscatter_file;
  s.rs = prepare_radiometry(categories, sim.radar, sim.derived, sigma0, backscatter_file);
  SlarImagingParams& imaging = s.rs.imaging;
  // A product's range sample k lies at range_of_bin(k) (ISCE's and NISAR's
  // slantRange: the sample's centre), so bin k spans half a spacing either
  // side of it, as the radar-grid layers take it (store_maps).
  imaging.range.near_m = g.range_of_bin(w.bin0 - 0.5);
  imaging.range.bin_m = g.range_spacing_m;
  imaging.range.count = w.bins;
  complete_slar_setup(sim, s.rs, dem_grid(dem, acq.ellipsoid));
  s.gain2.emplace(imaging.elevation_gain, imaging.peak_gain, sim.radar.source_file);
  s.ctx = element_context(imaging, *s.gain2, s.rs.lut, w.bins);
}

void set_acquisition_ground_grid(AcquisitionSimulation& a) {
  const SlarImage& img = a.sim.image;
  a.sim.ground_grid = ground_range_grid(img.range, a.sensor_height_m,
                                        0.5 * (a.dem_min_m + a.dem_max_m), img.line_spacing_m);
}

}  // namespace ris::detail
