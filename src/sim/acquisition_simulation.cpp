#include "ris/sim/acquisition_simulation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "ris/backscatter/sigma0_lut.h"
#include "ris/scene/geo_frame.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/sim/slar_run_setup.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "sim/acquisition_frame.h"
#include "sim/acquisition_lines.h"

namespace ris {

namespace {

// Speed of light (m/s), for the acquisition's frequency.
constexpr double kLightSpeed_m_s = 299792458.0;

// A grid for the set-up's checks (SAR resolution against the DEM's
// posting): the DEM's cell size in metres at its centre, no arrays.
Scene dem_grid(const EllipsoidalDem& dem, const Ellipsoid& e) {
  Scene grid;
  grid.rows = dem.rows;
  grid.cols = dem.cols;
  const double lat = dem.lat0_rad + 0.5 * (dem.rows - 1) * dem.dlat_rad;
  grid.dx_m = std::abs(dem.dlon_rad) * e.prime_vertical_radius_m(lat) * std::cos(lat);
  grid.dy_m = std::abs(dem.dlat_rad) * e.meridional_radius_m(lat);
  return grid;
}

// The land cover's category at each DEM posting: the scene cell nearest
// it (PROJ from latitude/longitude into the scene's CRS), or `fallback`
// outside the scene and on its no-data cells. Serial, before the parallel
// run: a point PROJ cannot transform throws here, naming the scene.
std::vector<std::uint16_t> categories_on_dem(const EllipsoidalDem& dem, const Scene& scene,
                                             const std::string& source, std::uint16_t fallback) {
  const GeoFrame frame(scene.crs_wkt, source);
  std::vector<std::uint16_t> out(dem.height_m.size(), fallback);
  for (int r = 0; r < dem.rows; ++r) {
    for (int c = 0; c < dem.cols; ++c) {
      const auto [x, y] = frame.scene_from_lonlat(rad_to_deg(dem.lon0_rad + c * dem.dlon_rad),
                                                  rad_to_deg(dem.lat0_rad + r * dem.dlat_rad));
      const auto [col_f, row_f] = scene.grid_from_world(x, y);
      const int sr = static_cast<int>(std::floor(row_f)), sc = static_cast<int>(std::floor(col_f));
      if (!scene.contains(sr, sc) || scene.valid[scene.index(sr, sc)] == 0) continue;
      out[static_cast<std::size_t>(r) * static_cast<std::size_t>(dem.cols) +
          static_cast<std::size_t>(c)] = scene.category[scene.index(sr, sc)];
    }
  }
  return out;
}

}  // namespace

AcquisitionSimulation simulate_acquisition(const Acquisition& acq, const EllipsoidalDem& dem,
                                           const RadarParams& radar_in, const Sigma0Source& sigma0,
                                           const AcquisitionSimOptions& options) {
  const RadarGrid& g = acq.grid;
  const Ellipsoid& e = acq.ellipsoid;
  if (radar_in.mode == RadarMode::ppi) {
    throw InputError(radar_in.source_file, "mode",
                     "an acquisition's radar grid is a SLAR or SAR image; expected mode = \"slar\" "
                     "or \"sar\"");
  }
  if (radar_in.mode == RadarMode::sar && radar_in.sar.coherent) {
    throw InputError(radar_in.source_file, "sar.coherent",
                     "the coherent SAR is not run on an acquisition's grid yet; expected "
                     "coherent = false");
  }
  if (options.samples_per_bin < 1) {
    throw InputError("", "--samples-per-bin",
                     fmt::format("expected 1 or more, got {}", options.samples_per_bin));
  }
  AcquisitionSimulation out;
  out.earth = options.earth;
  out.category = options.category;
  const detail::AcquisitionFrame frame = detail::acquisition_frame(acq, dem, options.full_grid);
  const GridWindow w = frame.window;
  detail::check_in_memory_window(w, acq.source, options.full_grid);
  out.window = w;
  const float h_min = frame.dem_min_m, h_max = frame.dem_max_m;
  out.sensor_height_m = frame.sensor_height_m;
  out.ground_azimuth_spacing_m = frame.ground_azimuth_spacing_m;

  // The radar at the acquisition's wavelength.
  SlarSimulation& sim = out.sim;
  sim.radar = radar_at_band(radar_in, kLightSpeed_m_s / g.wavelength_m, radar_in.polarisation);
  sim.radar.earth = options.earth;
  sim.derived = derive(sim.radar);

  // The engine's layout: the window's lines, the profile's points as samples.
  std::vector<float> local_deg(w.size());
  std::vector<std::uint8_t> mask(w.size());
  detail::AcquisitionRun run{acq,     dem,   w,     options.earth,          options.category,
                             nullptr, h_min, h_max, options.samples_per_bin};
  std::vector<std::uint16_t> dem_category;
  std::vector<std::uint16_t> categories{options.category};
  if (options.land_cover != nullptr) {
    dem_category =
        categories_on_dem(dem, *options.land_cover, options.land_cover_source, options.category);
    categories = dem_category;
    std::sort(categories.begin(), categories.end());
    categories.erase(std::unique(categories.begin(), categories.end()), categories.end());
    run.dem_category = dem_category.data();
    out.land_cover_source = options.land_cover_source;
  }
  out.profile_points = detail::acquisition_max_points(run);
  run.max_points = out.profile_points;
  SlarGeometry& layout = sim.geometry;
  layout.lines = w.lines;
  layout.samples = static_cast<int>(out.profile_points);
  layout.line_spacing_m = out.ground_azimuth_spacing_m;
  layout.altitude_m = out.sensor_height_m;
  layout.sample_step_m = 1.0;
  layout.first_sample_u_m = 1.0;  // no sample is "behind" the sensor
  run.layout = &layout;
  run.local_incidence_deg = local_deg.data();
  run.mask = mask.data();

  // Radiometry (one category), the grid's slant-range bins, SAR windows and
  // noise.
  const std::string backscatter_file =
      options.backscatter_file.empty() ? sigma0.description() : options.backscatter_file;
  RadiometrySetup rs =
      prepare_radiometry(categories, sim.radar, sim.derived, sigma0, backscatter_file);
  SlarImagingParams& imaging = rs.imaging;
  imaging.range.near_m = g.range_of_bin(w.bin0);
  imaging.range.bin_m = g.range_spacing_m;
  imaging.range.count = w.bins;
  complete_slar_setup(sim, rs, dem_grid(dem, e));

  // The lines through the engine.
  SlarLineProfiles prof;
  prof.allocate(w.lines, w.bins);
  SlarLineCounts counts;
  const TwoWayGainTable gain2(imaging.elevation_gain, imaging.peak_gain, sim.radar.source_file);
  const detail::SlarElementContext ctx = detail::element_context(imaging, gain2, rs.lut, w.bins);
  const detail::LineStages stages{ctx, LineLookFrame{}, !gain2.uniform(), imaging.range_window_bins,
                                  nullptr};
  detail::run_line_blocks(layout, stages, 0, w.lines, 16, prof, counts, [&](detail::LineScratch&) {
    return detail::AcquisitionThreadSource{run, {}, {}, {}, {}, {}, {}, {}, {}};
  });
  set_sample_counts(layout, counts);
  check_swath_hits_scene(prof.samples_in_swath, imaging.range, counts, sim.radar.source_file);
  sim.image = slar_image_from_profiles(prof, imaging, layout.line_spacing_m);
  SlarImage& img = sim.image;
  finish_slar_image(sim, img, rs.terms);
  // The ground-range presentation over the flat Earth at the DEM's mid height
  // (render_slar's ground_range picture).
  sim.ground_grid =
      ground_range_grid(img.range, out.sensor_height_m, 0.5 * (h_min + h_max), img.line_spacing_m);
  out.acquisition_source = acq.source;
  out.acquisition_format = acq.format;
  out.mission = acq.mission;
  out.polarisation = acq.polarisation;
  out.grid = g;
  out.acquisition_notes = acq.notes;
  out.dem_source = dem.source;
  out.dem_vertical_note = dem.vertical_note;
  out.dem_min_m = h_min;
  out.dem_max_m = h_max;
  out.local_incidence_deg = std::move(local_deg);
  out.layover_shadow_mask = std::move(mask);
  return out;
}

}  // namespace ris
