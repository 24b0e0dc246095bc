// The pixels `ris calibrate` fits (docs/calibrate.md): a calibrated image
// on an acquisition's radar grid, with each pixel's local incidence and
// backscatter category from the acquisition's geometry over a DEM and a
// land cover, as `ris simulate --acquisition P --dem D --land-cover L`
// places them.
//
// Per pixel of the DEM's window of the grid (ris/geometry/topo.h,
// dem_window; the window `ris simulate --acquisition` writes), the radar
// pass of `ris topo` (topo_radar_line) gives the ground point (rdr2geo on
// the DEM), its local incidence theta_l (to the DEM's facet normal), the
// incidence to the ellipsoid's normal theta_e and the layover/shadow mask.
//
// Area normalisation. A calibrated product is referenced to the ellipsoid
// (beta0 per unit slant-plane area; sigma0_e = beta0 sin(theta_e), ESA-EOPG-
// CSCOP-TN-0002), while the simulation's sigma0 is per unit true (tilted)
// area at the local incidence. For a facet tilted in range, its area in a
// pixel of slant-plane area A_beta is A_beta / sin(theta_l), so
//
//   sigma0(theta_l) = beta0 sin(theta_l) = sigma0_e sin(theta_l) / sin(theta_e)
//
// (Ulander 1996, "Radiometric slope correction of synthetic-aperture radar
// images", IEEE TGRS 34(5), the local-incidence case of the projection-angle
// correction; exact for range slopes, approximate where the terrain also
// slopes along track). On level ground theta_l = theta_e and sigma0 is the
// product's own.
//
// Category: the land cover's category at the DEM posting nearest the
// pixel's ground point (the land cover read at that posting, nearest cell,
// as the simulation takes it: ris/sim/acquisition_simulation.h), or
// `fallback` outside the land cover. Excluded (category -1): pixels without
// a ground point, in layover or shadow (their power is not one facet's),
// with no image data, and pixels within `edge_px` pixels of another category
// (mixed pixels at boundaries).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ris/geometry/topo.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/scene/scene.h"
#include "ris/sensor/acquisition.h"

namespace ris {

enum class CalibratedQuantity { sigma0, beta0 };

struct CalibrationImage {
  std::string source;  // named in messages
  int cols = 0, rows = 0;
  std::vector<float> values;  // linear, rows x cols; NaN: no data
  CalibratedQuantity quantity = CalibratedQuantity::beta0;
};

struct CalibrationSampleOptions {
  const Scene* land_cover = nullptr;  // nullptr: every pixel is `fallback`
  std::string land_cover_source;
  std::uint16_t fallback = 1;
  int edge_px = 1;
  int threads = 0;  // 0: OpenMP's default
};

struct CalibrationSamples {
  GridWindow window;
  bool image_was_full_grid = false;        // the image held the whole grid; its window was taken
  std::vector<float> sigma0;               // per unit true area, linear (NaN: none)
  std::vector<float> local_incidence_deg;  // NaN: no ground point
  std::vector<std::int32_t> category;      // -1: excluded
  // Pixels excluded and why (a pixel counts once, first reason).
  std::int64_t no_ground = 0, layover_shadow = 0, no_image_data = 0, boundary = 0;
};

// Throws InputError naming the image when its size is neither the DEM's
// window of the grid nor the whole grid, when the DEM misses the grid, or
// when the land cover has no CRS.
CalibrationSamples acquisition_calibration_samples(const Acquisition& acq,
                                                   const EllipsoidalDem& dem,
                                                   const CalibrationImage& image,
                                                   const CalibrationSampleOptions& options);

}  // namespace ris
