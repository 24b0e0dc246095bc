#include "ris/image/acquisition_georef.h"

#include <ogr_spatialref.h>

#include <algorithm>
#include <cmath>

#include "ris/geometry/zero_doppler.h"
#include "ris/io/gdal_util.h"
#include "ris/util/units.h"

namespace ris {

namespace {

// n indices from 0 to count - 1, both included (one when count is 1).
std::vector<int> spread(int count, int per_side) {
  const int n = std::max(1, std::min(per_side, count));
  std::vector<int> v(static_cast<std::size_t>(n), 0);
  for (int i = 0; i < n; ++i) {
    v[static_cast<std::size_t>(i)] =
        n == 1 ? 0 : static_cast<int>(std::lround(double(count - 1) * i / (n - 1)));
  }
  return v;
}

}  // namespace

AcquisitionTieGrid acquisition_tie_grid(const GridWindow& window, int per_side) {
  return {spread(window.lines, per_side), spread(window.bins, per_side)};
}

Georef acquisition_georef_frame() {
  OGRSpatialReference wgs84;
  wgs84.importFromEPSG(4326);
  Georef g;
  g.crs_wkt = wkt_of(wgs84);
  return g;
}

void add_acquisition_tie_line(const Acquisition& acq, const EllipsoidalDem& dem,
                              const GridWindow& w, int l, const std::vector<int>& bins,
                              double flat_height_m, Georef& out) {
  const RadarGrid& g = acq.grid;
  const Ellipsoid& e = acq.ellipsoid;
  // As topo_radar_line: the line's zero-Doppler frame, rdr2geo per bin.
  const ZeroDopplerFrame f(acq.orbit.interpolate(g.time_of_line(w.line0 + l)), g.look_side, e);
  const double h_flat = std::isfinite(flat_height_m) ? flat_height_m : 0.0;
  const auto dem_h = [&dem](double la, double lo) { return dem.height_at(la, lo); };
  const auto flat_h = [h_flat](double, double) { return h_flat; };
  for (const int k : bins) {
    const double r_m = g.range_of_bin(w.bin0 + k);
    GroundPoint p = rdr2geo(f, e, r_m, dem_h, h_flat);
    if (!p.converged) p = rdr2geo(f, e, r_m, flat_h, h_flat);
    if (!p.converged) continue;  // no ground at this range (inside the nadir)
    out.gcps.push_back({k + 0.5, l + 0.5, rad_to_deg(p.geodetic.lon_rad),
                        rad_to_deg(p.geodetic.lat_rad), p.geodetic.height_m});
  }
}

Georef acquisition_georef(const Acquisition& acq, const EllipsoidalDem& dem,
                          const GridWindow& window, double flat_height_m, int per_side) {
  Georef g = acquisition_georef_frame();
  const AcquisitionTieGrid tie = acquisition_tie_grid(window, per_side);
  for (const int l : tie.lines)
    add_acquisition_tie_line(acq, dem, window, l, tie.bins, flat_height_m, g);
  return g;
}

}  // namespace ris
