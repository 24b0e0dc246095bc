// The speed benchmark of ris topo's DEM pass (`ris bench --topo`): the
// shipped airborne example acquisition (data/acquisitions/airborne-l-band-
// flight-line.toml: 500 lines x 600 bins, L band, 12.5 km up) over rolling
// hills on a DEM fine enough that, at one facet per DEM cell, the DEM pass
// places some 16 M DEM cells by geo2rdr (the "DEM cells/s").
//
// Example:
//   ris::TopoBenchResult r = ris::run_topo_bench({0.0625, 2, 3});
//   // r.dem_cells / r.dem_seconds: DEM cells per second, wall clock
#pragma once

#include <cstddef>

#include "ris/io/ellipsoidal_dem.h"
#include "ris/sensor/acquisition.h"

namespace ris {

// Rolling hills (about 230 +- 100 m) over the ground the acquisition's whole
// grid sees (its corners on the ellipsoid at 230 m, widened by 0.005 deg),
// at posting_arcsec postings in latitude and longitude.
EllipsoidalDem rolling_hills_dem(const Acquisition& a, double posting_arcsec);

struct TopoBenchOptions {
  double posting_arcsec = 0.0625;  // 1/16": 1.9 m x 1.2 m at 49 N, ~16 M cells
  int threads = 2;
  int repeats = 3;  // timed runs (the median is reported)
};

struct TopoBenchResult {
  int grid_lines = 0, grid_bins = 0;
  int dem_rows = 0, dem_cols = 0;
  std::size_t dem_cells = 0;  // placed by the DEM pass (one facet each)
  // Medians over the repeats.
  double dem_seconds = 0.0, dem_cpu_seconds = 0.0, radar_seconds = 0.0;
};

TopoBenchResult run_topo_bench(const TopoBenchOptions& options);

}  // namespace ris
