#include "sim/modes/acquisition_calibration.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ris/geometry/zero_doppler.h"
#include "ris/util/units.h"

namespace ris::detail {

SlantCalibration acquisition_calibration(const AcquisitionRun& run, const SlarImagingParams& p,
                                         double line_spacing_m, double reference_height_m) {
  const RadarGrid& g = run.acq.grid;
  const Ellipsoid& e = run.acq.ellipsoid;
  const double mid_line = run.window.line0 + 0.5 * (run.window.lines - 1);
  const OrbitState st = run.acq.orbit.interpolate(g.time_of_line(mid_line));
  const ZeroDopplerFrame f(st, g.look_side, e);
  // A line's along-track ground extent per unit radius (as the lines'
  // elements take their area, sim/sources/acquisition_lines.cpp).
  const double az_per_radius = st.velocity_m_s.norm() * g.line_interval_s / st.position_m.norm();
  const Geodetic& sub = f.sensor_geodetic;
  const double h_ref = reference_height_m;
  const auto n = static_cast<std::size_t>(p.range.count);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> look(n, nan), incidence(n, nan), azimuth_cell(n, nan);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = p.range.centre_m(static_cast<int>(i));
    // The image's azimuth cell in lines: its window, or R phi over the
    // layout's line spacing (ris/image/slar_azimuth_integrator.h).
    const double lines = p.azimuth_window_lines > 0.0
                             ? p.azimuth_window_lines
                             : slar_footprint_m(r, p.azimuth_beamwidth_rad) / line_spacing_m;
    if (run.earth == EarthModel::flat) {
      const double height = sub.height_m - h_ref;
      if (!(height > 0.0) || !(r > height)) continue;
      look[i] = incidence[i] = std::acos(height / r);
      azimuth_cell[i] = lines * az_per_radius * e.to_ecef({sub.lat_rad, sub.lon_rad, h_ref}).norm();
      continue;
    }
    const double th = ray_look_of_range(f, e, h_ref, h_ref, r);
    Vec3 x;
    if (!(th > 0.0) || !ground_at(f, e, h_ref, th, h_ref, x)) continue;
    const Vec3 to_sensor = f.sensor_m - x;
    const Vec3 l = to_sensor * (1.0 / to_sensor.norm());
    // The gain's angle as the elements take it: from the geodetic nadir.
    look[i] = std::acos(std::clamp(f.nadir_normal.dot(l), -1.0, 1.0));
    incidence[i] = deg_to_rad(look_angles(e, f.sensor_m, x).incidence_deg);
    azimuth_cell[i] = lines * az_per_radius * x.norm();
  }
  return calibration_from_angles(p, h_ref, look, incidence, azimuth_cell);
}

}  // namespace ris::detail
