#include "ris/perf/topo_bench.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "ris/geometry/topo.h"
#include "ris/geometry/zero_doppler.h"
#include "ris/util/data_dir.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

EllipsoidalDem rolling_hills_dem(const Acquisition& a, double posting_arcsec) {
  const LatLonBox box = grid_corner_box(a, 230.0);
  double la0 = box.lat_min_rad, la1 = box.lat_max_rad, lo0 = box.lon_min_rad, lo1 = box.lon_max_rad;
  const double pad = deg_to_rad(0.005), step = deg_to_rad(posting_arcsec / 3600.0);
  la0 -= pad, la1 += pad, lo0 -= pad, lo1 += pad;
  const int rows = static_cast<int>((la1 - la0) / step) + 1;
  const int cols = static_cast<int>((lo1 - lo0) / step) + 1;
  EllipsoidalDem d = flat_ellipsoidal_dem(la0, la0 + (rows - 1) * step, lo0,
                                          lo0 + (cols - 1) * step, rows, cols, 230.0);
  // Hills of a few hundred metres' wavelength, whatever the posting.
  const double k = deg_to_rad(posting_arcsec / 3600.0) * 6.4e6 / 60.0;
  for (int r = 0; r < rows; ++r) {
    for (int c = 0; c < cols; ++c) {
      d.height_m[static_cast<std::size_t>(r) * cols + c] =
          static_cast<float>(230.0 + 50.0 * (std::sin(r * k) + std::cos(c * 0.7 * k)));
    }
  }
  d.source = "rolling hills (ris bench --topo)";
  return d;
}

TopoBenchResult run_topo_bench(const TopoBenchOptions& o) {
  if (!(o.posting_arcsec > 0.0)) {
    throw InputError("", "--topo-posting", "expected a positive posting in arc-seconds");
  }
  if (o.repeats < 1) throw InputError("", "--repeats", "expected 1 or more");
  const Acquisition a =
      read_acquisition(data_dir() / "acquisitions" / "airborne-l-band-flight-line.toml");
  const EllipsoidalDem dem = rolling_hills_dem(a, o.posting_arcsec);
  TopoOptions t;
  t.oversample = 1;  // one facet per DEM cell: DEM cells per second
  t.threads = o.threads;
  std::vector<double> wall, cpu, radar;
  TopoBenchResult r;
  for (int i = 0; i < o.repeats; ++i) {
    const TopoLayers layers = compute_topo(a, dem, t);
    wall.push_back(layers.dem_seconds);
    cpu.push_back(layers.dem_cpu_seconds);
    radar.push_back(layers.radar_seconds);
    r.dem_cells = layers.dem_cells;
    r.grid_lines = layers.window.lines;
    r.grid_bins = layers.window.bins;
  }
  const auto median = [](std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
    return v[v.size() / 2];
  };
  r.dem_rows = dem.rows;
  r.dem_cols = dem.cols;
  r.dem_seconds = median(wall);
  r.dem_cpu_seconds = median(cpu);
  r.radar_seconds = median(radar);
  return r;
}

}  // namespace ris
