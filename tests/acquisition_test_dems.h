// Test acquisitions and DEMs shared by the topo and acquisition-simulation
// tests: the airborne example on a small grid, and a DEM around it (flat, or
// with a ridge along the track).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "acquisition_paths.h"
#include "ris/geometry/topo.h"
#include "ris/geometry/zero_doppler.h"
#include "ris/io/ellipsoidal_dem.h"
#include "ris/sensor/acquisition.h"
#include "ris/util/units.h"

namespace ris::test {

// The airborne example on a smaller grid (60 lines x 300 bins of 12.5 m).
inline Acquisition small_airborne() {
  Acquisition a = read_acquisition(test::example_acquisition("airborne-l-band-flight-line.toml"));
  a.grid.lines = 60;
  a.grid.line_interval_s = 0.1;
  a.grid.bins = 300;
  a.grid.range_spacing_m = 12.5;
  return a;
}

// A DEM of 1 arc-second postings around the grid: flat at 230 m, with
// (ridge_m > 0) a ridge of triangular section along the track, its crest at
// mid-swath, slopes of atan(ridge_m / half_width_m).
inline EllipsoidalDem dem_for(const Acquisition& a, double ridge_m, double half_width_m) {
  const RadarGrid& g = a.grid;
  const auto flat = [](double, double) { return 230.0; };
  const LatLonBox box = grid_corner_box(a, 230.0);
  double la0 = box.lat_min_rad, la1 = box.lat_max_rad, lo0 = box.lon_min_rad, lo1 = box.lon_max_rad;
  const double pad = deg_to_rad(0.01), step = deg_to_rad(1.0 / 3600.0);
  la0 -= pad, la1 += pad, lo0 -= pad, lo1 += pad;
  const int rows = static_cast<int>((la1 - la0) / step) + 1;
  const int cols = static_cast<int>((lo1 - lo0) / step) + 1;
  EllipsoidalDem d = flat_ellipsoidal_dem(la0, la0 + (rows - 1) * step, lo0,
                                          lo0 + (cols - 1) * step, rows, cols, 230.0);
  if (ridge_m > 0.0) {
    const ZeroDopplerFrame f(a.orbit.interpolate(g.time_of_line(0.5 * g.lines)), g.look_side,
                             a.ellipsoid);
    const GroundPoint crest = rdr2geo(f, a.ellipsoid, g.range_of_bin(0.5 * g.bins), flat, 230.0);
    for (int r = 0; r < rows; ++r) {
      for (int c = 0; c < cols; ++c) {
        const Vec3 x =
            a.ellipsoid.to_ecef({d.lat0_rad + r * d.dlat_rad, d.lon0_rad + c * d.dlon_rad, 230.0});
        const double across = (x - crest.ecef_m).dot(f.side);
        d.height_m[static_cast<std::size_t>(r) * cols + c] = static_cast<float>(
            230.0 + ridge_m * std::max(0.0, 1.0 - std::abs(across) / half_width_m));
      }
    }
  }
  return d;
}

}  // namespace ris::test
