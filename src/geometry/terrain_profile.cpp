#include "ris/geometry/terrain_profile.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ris {

void trace_terrain_profile(const ZeroDopplerFrame& f, const Ellipsoid& e, const EllipsoidalDem& dem,
                           const ProfileSpan& span, bool keep_points, TerrainProfile& out) {
  constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
  const std::size_t n = span.points;
  const double h_ref = span.height_ref_m;
  const double dlook = (span.look_hi_rad - span.look_lo_rad) / static_cast<double>(n - 1);
  out.look_rad.resize(n);
  out.range_m.resize(n);
  out.flags.assign(n, 0);
  if (keep_points) {
    out.ground_m.resize(n);
    out.lat_rad.resize(n);
    out.lon_rad.resize(n);
    out.height_m.resize(n);
  }
  const double ia2 = 1.0 / ((e.semi_major_m() + h_ref) * (e.semi_major_m() + h_ref));
  const double ib2 = 1.0 / ((e.semi_minor_m() + h_ref) * (e.semi_minor_m() + h_ref));
  for (std::size_t k = 0; k < n; ++k) {
    const double th = span.look_lo_rad + static_cast<double>(k) * dlook;
    const double t = f.range_to_ellipsoid(th, e, h_ref);
    out.look_rad[k] = kNan;
    out.range_m[k] = kNan;
    if (keep_points) out.height_m[k] = kNan;
    if (!std::isfinite(t)) continue;
    const Vec3 x0 = f.point(t, th);
    const Geodetic q = e.to_geodetic(x0);
    const double h = dem.height_at(q.lat_rad, q.lon_rad);
    if (!std::isfinite(h)) continue;
    // Up the normal of the inflated ellipsoid (its gradient: no trigonometry).
    const Vec3 up = Vec3{x0.x * ia2, x0.y * ia2, x0.z * ib2}.normalized();
    const Vec3 ground = x0 + up * (h - q.height_m);
    const Vec3 d = ground - f.sensor_m;
    out.look_rad[k] = std::atan2(d.dot(f.side), d.dot(f.nadir));
    out.range_m[k] = d.norm();
    if (keep_points) {
      // Moving along the (inflated) normal keeps latitude and longitude to
      // well under a millimetre at terrain heights.
      out.ground_m[k] = ground;
      out.lat_rad[k] = q.lat_rad;
      out.lon_rad[k] = q.lon_rad;
      out.height_m[k] = h;
    }
  }
}

void mark_shadow_layover(std::size_t n, const double* look, const double* range,
                         std::uint8_t* flags) {
  double max_look = -1e300, max_range = -1e300;
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(range[k])) continue;
    if (look[k] < max_look) flags[k] |= kMaskShadow;
    if (range[k] <= max_range) flags[k] |= kMaskLayover;
    max_look = std::max(max_look, look[k]);
    max_range = std::max(max_range, range[k]);
  }
  double min_range = 1e300;
  for (std::size_t k = n; k-- > 0;) {
    if (!std::isfinite(range[k])) continue;
    if (range[k] >= min_range) flags[k] |= kMaskLayover;
    min_range = std::min(min_range, range[k]);
  }
}

DemSlope dem_slope(const EllipsoidalDem& dem, const Ellipsoid& e, double lat, double lon,
                   double h) {
  const double dla = std::abs(dem.dlat_rad), dlo = std::abs(dem.dlon_rad);
  const auto diff = [&](double plus, double minus, double step) {
    if (std::isfinite(plus) && std::isfinite(minus)) return (plus - minus) / (2.0 * step);
    if (std::isfinite(plus)) return (plus - h) / step;
    if (std::isfinite(minus)) return (h - minus) / step;
    return 0.0;
  };
  const double step_e = dlo * e.prime_vertical_radius_m(lat) * std::cos(lat);
  const double step_n = dla * e.meridional_radius_m(lat);
  return {diff(dem.height_at(lat, lon + dlo), dem.height_at(lat, lon - dlo), step_e),
          diff(dem.height_at(lat + dla, lon), dem.height_at(lat - dla, lon), step_n)};
}

Vec3 dem_normal(const EllipsoidalDem& dem, const Ellipsoid& e, double lat, double lon, double h) {
  const DemSlope g = dem_slope(dem, e, lat, lon, h);
  const EnuBasis b = Ellipsoid::enu(lat, lon);
  return (b.east * -g.east + b.north * -g.north + b.up).normalized();
}

}  // namespace ris
