// A SLAR / SAR simulation on a real (or planned) acquisition's own radar
// grid (`ris simulate --acquisition P`, issue 15): the image has the
// product's lines and range bins, so it lies over the real image pixel for
// pixel. The terrain is a DEM on the WGS 84 ellipsoid; the orbit and grid
// are the product's (ris/sensor/acquisition.h).
//
// It runs through the one line engine (sim/engine/slar_line_engine.h) with the
// acquisition's line source (sim/sources/acquisition_lines.h: each azimuth line's
// terrain profile in its zero-Doppler plane, look geometry on the ellipsoid
// or the flat Earth, shadow and layover along it), then the stages every
// SLAR / SAR run shares: radiometry, image formation into the range
// profile, azimuth integration, switch corrections and SAR noise
// (ris/sim/slar_run_setup.h), and render_slar for speckle and greytones.
//
// What comes from where: the radar file gives power, antenna, mode, SAR
// resolution and looks, film and switches; the acquisition gives the
// wavelength (the radar is retuned to it, radar_at_band), the orbit, the
// slant-range grid and the line interval. The radar file's track and swath
// keys are not used.
//
// Example:
//   ris::Acquisition acq = ris::read_acquisition("winnipeg.h5");
//   ris::EllipsoidalDem dem = ris::read_ellipsoidal_dem("winnipeg_dem.tif");
//   ris::AcquisitionSimulation a = ris::simulate_acquisition(acq, dem, radar, *sigma0, {});
//   ris::SlarPictures pic = ris::render_slar(a.sim, 1);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ris/backscatter/sigma0_source.h"
#include "ris/geometry/topo.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/io/raster_io.h"
#include "ris/sensor/acquisition.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/slar_simulation.h"

namespace ris {

struct AcquisitionSimOptions {
  EarthModel earth = EarthModel::ellipsoid;
  // The backscatter category of every DEM cell (a DEM has no land cover);
  // 1 is wheat stubble in the default library (data/backscatter/ku-geometric.toml).
  std::uint16_t category = 1;
  // Land cover (optional): a ris scene in a projected CRS whose categories
  // the terrain takes, the scene cell nearest each DEM posting (postings
  // outside the scene or on its no-data cells take `category`). The heights
  // stay the DEM's.
  const Scene* land_cover = nullptr;
  std::string land_cover_source;  // named in messages and metadata
  bool full_grid = false;         // false: the window of the grid the DEM covers (as ris topo)
  int samples_per_bin = 3;        // terrain profile points per range bin (as ris topo's mask)
  std::string backscatter_file;   // named in messages
};

struct AcquisitionSimulation {
  SlarSimulation sim;  // image: window.lines x window.bins, the grid's bins
  GridWindow window;   // of the acquisition's grid
  EarthModel earth = EarthModel::ellipsoid;
  std::uint16_t category = 0;
  std::string land_cover_source;  // empty: one category for the whole DEM
  // Radar-grid layers (window lines x bins, as ris topo's): the local
  // incidence of the terrain nearest each bin's centre (degrees; NaN where
  // no terrain) and the layover/shadow mask (TopoMask bits).
  std::vector<float> local_incidence_deg;
  std::vector<std::uint8_t> layover_shadow_mask;
  // What metadata.json says of the inputs.
  std::string acquisition_source, acquisition_format, mission, polarisation;
  RadarGrid grid;
  std::vector<std::string> acquisition_notes;
  std::string dem_source, dem_vertical_note;
  float dem_min_m = 0.0f, dem_max_m = 0.0f;
  double ground_azimuth_spacing_m = 0.0;  // mid-window, the image's line spacing
  double sensor_height_m = 0.0;           // above the ellipsoid, mid-window
  std::size_t profile_points = 0;         // terrain points per line (at most)
  // The window's GCPs in latitude/longitude (ris/image/acquisition_georef.h),
  // carried by every product on the window's grid.
  Georef georef;
};

// Throws InputError for a DEM that misses the grid, a window over 50 M
// pixels, a category the backscatter source lacks, a swath with no terrain.
AcquisitionSimulation simulate_acquisition(const Acquisition& acq, const EllipsoidalDem& dem,
                                           const RadarParams& radar, const Sigma0Source& sigma0,
                                           const AcquisitionSimOptions& options = {});

}  // namespace ris
