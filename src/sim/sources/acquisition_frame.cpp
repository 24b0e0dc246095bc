#include "sim/sources/acquisition_frame.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ris/util/error.h"

namespace ris::detail {

namespace {

// The lowest and highest height with data (infinite when none has).
HeightRange height_extent(const EllipsoidalDem& dem) {
  float h_min = std::numeric_limits<float>::infinity(), h_max = -h_min;
  for (float h : dem.height_m) {
    if (std::isfinite(h)) {
      h_min = std::min(h_min, h);
      h_max = std::max(h_max, h);
    }
  }
  return {h_min, h_max};
}

// The frame given the DEM's grid (whole, a window or none of its heights)
// and its height range [lo, hi] (infinite: no height with data).
AcquisitionFrame frame_of(const Acquisition& acq, const EllipsoidalDem& dem, float lo, float hi,
                          bool full_grid) {
  const RadarGrid& g = acq.grid;
  const Ellipsoid& e = acq.ellipsoid;
  AcquisitionFrame f;
  f.window = full_grid ? GridWindow{0, g.lines, 0, g.bins} : dem_window(acq, dem, lo, hi);
  const GridWindow& w = f.window;
  if (w.lines == 0 || w.bins == 0) {
    throw InputError(
        dem.source, "",
        fmt::format("the DEM does not cover any pixel of {}'s radar grid", acq.source));
  }
  if (!std::isfinite(lo)) throw InputError(dem.source, "", "the DEM has no height with data");
  f.dem_min_m = lo;
  f.dem_max_m = hi;
  const double t_mid = g.time_of_line(w.line0 + 0.5 * (w.lines - 1));
  const OrbitState s_mid = acq.orbit.interpolate(t_mid);
  const Geodetic sub_mid = e.to_geodetic(s_mid.position_m);
  f.sensor_height_m = sub_mid.height_m;
  // The image's line spacing on the ground at mid-window: the sensor's
  // angular rate about the Earth's centre at the terrain's radius (as ris
  // topo's beta area).
  const double rho_ground = e.to_ecef({sub_mid.lat_rad, sub_mid.lon_rad, 0.5 * (lo + hi)}).norm();
  f.ground_azimuth_spacing_m =
      s_mid.velocity_m_s.norm() * g.line_interval_s * rho_ground / s_mid.position_m.norm();
  return f;
}

}  // namespace

HeightRange dem_height_range(const EllipsoidalDem& dem) {
  const HeightRange h = height_extent(dem);
  if (!std::isfinite(h.min_m)) throw InputError(dem.source, "", "the DEM has no height with data");
  return h;
}

AcquisitionFrame acquisition_frame(const Acquisition& acq, const EllipsoidalDem& dem,
                                   bool full_grid) {
  const HeightRange h = height_extent(dem);
  AcquisitionFrame f = frame_of(acq, dem, h.min_m, h.max_m, full_grid);
  f.dem_vertical_note = dem.vertical_note;
  return f;
}

AcquisitionFrame acquisition_frame(const Acquisition& acq, const EllipsoidalDem& grid,
                                   const EllipsoidalDemSummary& summary, bool full_grid) {
  AcquisitionFrame f = frame_of(acq, grid, summary.min_m, summary.max_m, full_grid);
  f.dem_vertical_note = summary.vertical_note;
  return f;
}

void check_in_memory_window(const GridWindow& w, const std::string& acquisition_source,
                            bool full_grid) {
  if (w.size() <= kMaxInMemoryPixels) return;
  throw InputError(acquisition_source, full_grid ? "--full-grid" : "--dem",
                   fmt::format("the window is {} lines x {} bins ({:.0f} M pixels); at most {} M "
                               "pixels in memory: stream the run (--stream), choose one burst "
                               "(--burst), a smaller DEM, or drop --full-grid",
                               w.lines, w.bins, static_cast<double>(w.size()) / 1e6,
                               kMaxInMemoryPixels / 1'000'000));
}

}  // namespace ris::detail
