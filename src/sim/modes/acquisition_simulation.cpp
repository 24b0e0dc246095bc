#include "ris/sim/acquisition_simulation.h"

#include "ris/image/acquisition_georef.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/sim/slar_run_setup.h"
#include "sim/modes/acquisition_calibration.h"
#include "sim/modes/acquisition_setup.h"
#include "sim/sources/acquisition_frame.h"
#include "sim/sources/acquisition_lines.h"

namespace ris {

AcquisitionSimulation simulate_acquisition(const Acquisition& acq, const EllipsoidalDem& dem,
                                           const RadarParams& radar_in, const Sigma0Source& sigma0,
                                           const AcquisitionSimOptions& options) {
  detail::check_acquisition_radar(radar_in, options);
  const detail::AcquisitionFrame frame = detail::acquisition_frame(acq, dem, options.full_grid);
  const GridWindow w = frame.window;
  detail::check_in_memory_window(w, acq.source, options.full_grid);
  detail::AcquisitionSetup s;
  detail::set_up_acquisition(acq, dem, radar_in, sigma0, options, frame, s);
  AcquisitionSimulation& out = s.out;
  SlarSimulation& sim = out.sim;
  const SlarGeometry& layout = sim.geometry;
  const SlarImagingParams& imaging = s.rs.imaging;
  detail::AcquisitionRun& run = *s.run;
  std::vector<float> local_deg(w.size());
  std::vector<std::uint8_t> mask(w.size());
  run.local_incidence_deg = local_deg.data();
  run.mask = mask.data();

  // The lines through the engine.
  SlarLineProfiles prof;
  prof.allocate(w.lines, w.bins);
  SlarLineCounts counts;
  detail::run_line_blocks(
      layout, s.stages(), 0, w.lines, 16, prof, counts, [&](detail::LineScratch&) {
        return detail::AcquisitionThreadSource{run, {}, {}, {}, {}, {}, {}, {}, {}};
      });
  set_sample_counts(sim.geometry, counts);
  check_swath_hits_scene(prof.samples_in_swath, imaging.range, counts, sim.radar.source_file);
  sim.image = slar_image_from_profiles(prof, imaging, layout.line_spacing_m);
  finish_slar_image(sim, sim.image, s.rs.terms);
  detail::set_acquisition_ground_grid(out);
  // Its calibration over the ground grid's reference height, unless a
  // switched-off factor put the reference system's in.
  if (!sim.range_corrected && !sim.area_corrected) {
    sim.calibration = detail::acquisition_calibration(run, imaging, layout.line_spacing_m,
                                                      sim.ground_grid.reference_height_m);
  }
  // The products' GCPs, from the grid and the DEM (as ris topo's layers).
  out.georef = acquisition_georef(acq, dem, w, 0.5 * (double(out.dem_min_m) + out.dem_max_m));
  out.local_incidence_deg = std::move(local_deg);
  out.layover_shadow_mask = std::move(mask);
  return std::move(out);
}

}  // namespace ris
