// Radar-geometry layers on an acquisition's own radar grid, like ISCE's
// topo: for every (line, bin) the ground point on the DEM and how the radar
// sees it, plus the terrain's gamma-naught normalisation area and a
// Muhleman simulated amplitude (docs/geometry.md).
//
// Two passes, both line- or row-parallel with per-thread scratch allocated
// once, both giving the same bytes for any thread count:
//  1. radar pass, one image line at a time (topo_radar_line): rdr2geo of
//     every bin on the DEM -> latitude, longitude, height, incidence (to the
//     ellipsoid normal), local incidence (to the DEM's facet normal), look
//     angle, heading; and the line's layover/shadow mask from a dense terrain
//     profile in its zero-Doppler plane (0 none, 1 shadow, 2 layover, 3 both).
//  2. DEM pass (the geo2rdr of every DEM facet, the costly step): each DEM
//     cell, cut into k x k facets so that facets are smaller than pixels,
//     is placed in the radar grid by geo2rdr; its area projected on the plane
//     perpendicular to the look direction (Small 2011, "Flattening gamma:
//     radiometric terrain correction for SAR imagery", IEEE TGRS 49(8),
//     eq. 8-11; sarsen's compute_gamma_area) and its Muhleman power
//     sigma0(local incidence) x area are spread bilinearly over the four
//     nearest pixels (sarsen's gamma_weights_bilinear). Sums are kept in
//     64-bit fixed point (2^-30 m^2), so the order of addition, and hence
//     the thread count, cannot change a bit.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "ris/geometry/terrain_profile.h"
#include "ris/geometry/zero_doppler.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/sensor/acquisition.h"

namespace ris {

// A rectangle of the acquisition's grid: lines line0.. and bins bin0..
struct GridWindow {
  int line0 = 0, lines = 0;
  int bin0 = 0, bins = 0;
  std::size_t size() const { return static_cast<std::size_t>(lines) * bins; }
};

struct TopoOptions {
  int oversample = 0;      // facets per DEM cell side; 0: automatic (facets < half a pixel)
  bool full_grid = false;  // false: the window of the grid the DEM covers
  int threads = 0;         // 0: OpenMP's default
};

struct TopoLayers {
  GridWindow window;
  std::vector<double> lat_deg, lon_deg;
  std::vector<float> height_m;
  std::vector<float> incidence_deg;             // to the ellipsoid normal
  std::vector<float> incidence_geocentric_deg;  // to the geocentric radius
  std::vector<float> local_incidence_deg;       // to the DEM facet normal
  std::vector<float> look_deg;                  // at the sensor, from the geodetic nadir
  std::vector<float> heading_deg;               // platform track, clockwise from north
  std::vector<std::uint8_t> mask;               // TopoMask bits
  std::vector<float> gamma_area_m2;             // projected area (Small 2011)
  std::vector<float> simulated_amplitude;       // sqrt(beta0) of a Muhleman surface
  // Statistics of the run.
  int oversample = 1;
  std::size_t dem_cells = 0;                      // DEM cells placed by the DEM pass
  std::size_t dem_facets = 0;                     // geo2rdr evaluations (cells x oversample^2)
  double radar_seconds = 0.0, dem_seconds = 0.0;  // wall clock
  double dem_cpu_seconds = 0.0;                   // CPU time of all threads
  std::size_t unconverged = 0;                    // bins whose rdr2geo did not converge (no data)
  double beta_area_m2 = 0.0;  // slant range spacing x mid-swath ground azimuth spacing
};

// Per-line geometry of one radar line: what a line source of the simulation
// engine needs (slant range is the grid's). Spans of window.bins values.
struct TopoLineView {
  double* lat_deg;
  double* lon_deg;
  float* height_m;
  float* incidence_deg;
  float* incidence_geocentric_deg;
  float* local_incidence_deg;
  float* look_deg;
  float* heading_deg;
  std::uint8_t* mask;
};

// Scratch for topo_radar_line (the terrain profile); reused across lines.
struct TopoLineScratch {
  TerrainProfile profile;
  std::vector<int> count, shadowed, layover;
  double dem_mean_height_m = std::nan("");  // first guess of rdr2geo, computed once
};

// Fills one line of the radar pass; returns the number of bins whose rdr2geo
// did not converge (their values are NaN, mask 0).
std::size_t topo_radar_line(const Acquisition& acq, const EllipsoidalDem& dem,
                            const GridWindow& window, int line, const TopoLineView& out,
                            TopoLineScratch& scratch);

// The window of the acquisition's grid that the DEM covers (geo2rdr of the
// DEM's outline at its lowest and highest heights, widened by two pixels),
// clipped to the grid; empty (lines = 0) when they do not overlap.
GridWindow dem_window(const Acquisition& acq, const EllipsoidalDem& dem);
// The same for heights in [lo, hi] (the DEM's range, summarised without
// holding its heights: dem may be a window or the file's grid alone).
GridWindow dem_window(const Acquisition& acq, const EllipsoidalDem& dem, float lo, float hi);

// The latitude/longitude box (radians) of the grid's four corner pixels on
// the ellipsoid raised to height_m (rdr2geo), e.g. for a DEM that covers
// the grid.
struct LatLonBox {
  double lat_min_rad = 0.0, lat_max_rad = 0.0, lon_min_rad = 0.0, lon_max_rad = 0.0;
};
LatLonBox grid_corner_box(const Acquisition& acq, double height_m);

TopoLayers compute_topo(const Acquisition& acq, const EllipsoidalDem& dem,
                        const TopoOptions& options);

}  // namespace ris
