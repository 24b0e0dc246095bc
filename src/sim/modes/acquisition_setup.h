// Internal: an acquisition run set up, everything before its lines run
// through the engine. The in-memory run (ris/sim/acquisition_simulation.h)
// and the streamed run (ris/sim/acquisition_stream.h) share it, so both
// simulate the same lines: the radar retuned to the acquisition's
// wavelength, the engine's layout (the window's lines, the profile's points
// as samples), the land cover on the DEM, the radiometry and the stages.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/sensor/acquisition.h"
#include "ris/sim/acquisition_simulation.h"
#include "ris/sim/radiometry_setup.h"
#include "sim/engine/slar_line_engine.h"
#include "sim/sources/acquisition_frame.h"
#include "sim/sources/acquisition_lines.h"

namespace ris::detail {

// Built in place (set_up_acquisition) and never moved: `run` points at
// out.sim.geometry and dem_category, the stages at gain2 and rs.lut.
struct AcquisitionSetup {
  AcquisitionSetup() = default;
  AcquisitionSetup(const AcquisitionSetup&) = delete;
  AcquisitionSetup& operator=(const AcquisitionSetup&) = delete;

  // The run's scalars and inputs for metadata.json; out.sim holds the radar,
  // its derived values and the layout, no image yet.
  AcquisitionSimulation out;
  RadiometrySetup rs;
  std::vector<std::uint16_t> dem_category;  // land cover on the DEM's postings
  // The lines' source; its local_incidence_deg and mask are the caller's.
  std::optional<AcquisitionRun> run;
  std::optional<TwoWayGainTable> gain2;
  SlarElementContext ctx;

  LineStages stages() const {
    return {ctx, LineLookFrame{}, !gain2->uniform(), rs.imaging.range_window_bins, nullptr};
  }
};

// What an acquisition run refuses before it reads its frame: a PPI or
// coherent SAR radar, fewer than one profile point per bin (InputError).
void check_acquisition_radar(const RadarParams& radar, const AcquisitionSimOptions& options);

// Throws InputError for a category the backscatter source lacks. dem: the
// whole DEM, or (a streamed run) its grid alone with categories_used, the
// land cover's categories over the whole DEM (sorted, unique); the run's
// dem_category is then the caller's, block by block.
void set_up_acquisition(const Acquisition& acq, const EllipsoidalDem& dem, const RadarParams& radar,
                        const Sigma0Source& sigma0, const AcquisitionSimOptions& options,
                        const AcquisitionFrame& frame, AcquisitionSetup& s,
                        const std::vector<std::uint16_t>* categories_used = nullptr);

// The land cover's category at each posting the DEM holds (a window's
// too): the scene cell nearest it (PROJ from latitude/longitude into the
// scene's CRS), or `fallback` outside the scene and on its no-data cells.
// Serial, before the parallel run: a point PROJ cannot transform throws
// here, naming the scene.
std::vector<std::uint16_t> categories_on_dem(const EllipsoidalDem& dem, const Scene& scene,
                                             const std::string& source, std::uint16_t fallback);

// The distinct values, sorted.
std::vector<std::uint16_t> sorted_categories(std::vector<std::uint16_t> c);

// The ground-range presentation over the flat Earth at the DEM's mid height
// (render_slar's ground_range picture), once the image's range and line
// spacing are set.
void set_acquisition_ground_grid(AcquisitionSimulation& a);

}  // namespace ris::detail
