#include "sim/sources/acquisition_lines.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>
#include <omp.h>

#include "ris/util/resource_guard.h"
#include "ris/util/units.h"

namespace ris::detail {

namespace {
constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr float kNanF = std::numeric_limits<float>::quiet_NaN();
// How much denser than over the swath at the DEM's mid height a profile's
// points may be (span_of_line). Every run of the suite stays under it (the
// densest, a 15-deg plane over 200 bins, 3.4 times).
constexpr double kMaxDensity = 4.0;
// Each thread's scratch per profile point: the engine's line (LineScratch,
// 57 bytes; its element pass, 24), the profile (65) and the source's look,
// range and ground distance (24), rounded up.
constexpr std::int64_t kScratchBytesPerPoint = 192;

ZeroDopplerFrame frame_of_line(const Acquisition& acq, int grid_line) {
  const OrbitState st = acq.orbit.interpolate(acq.grid.time_of_line(grid_line));
  return ZeroDopplerFrame(st, acq.grid.look_side, acq.ellipsoid);
}
}  // namespace

std::uint16_t AcquisitionRun::category_at(double lat_rad, double lon_rad) const {
  if (dem_category == nullptr) return category;
  // The nearest posting of the file's grid, then its place in the held
  // window (the whole DEM: the same).
  const long r = std::clamp(std::lround((lat_rad - dem.lat0_rad) / dem.dlat_rad), 0L,
                            static_cast<long>(dem.all_rows() - 1)) -
                 dem.row0;
  const long c = std::clamp(std::lround((lon_rad - dem.lon0_rad) / dem.dlon_rad), 0L,
                            static_cast<long>(dem.all_cols() - 1)) -
                 dem.col0;
  return dem_category[static_cast<std::size_t>(r) * static_cast<std::size_t>(dem.cols) +
                      static_cast<std::size_t>(c)];
}

// Where trace_terrain_profile puts the ground at ray look angle th and
// height h: the ray met on the ellipsoid raised to h_ref (the profile's
// reference), then moved along that surface's normal to h. False when the
// ray misses it.
bool ground_at(const ZeroDopplerFrame& f, const Ellipsoid& e, double h_ref, double th, double h,
               Vec3& out) {
  const double t = f.range_to_ellipsoid(th, e, h_ref);
  if (!std::isfinite(t)) return false;
  const double ia2 = 1.0 / ((e.semi_major_m() + h_ref) * (e.semi_major_m() + h_ref));
  const double ib2 = 1.0 / ((e.semi_minor_m() + h_ref) * (e.semi_minor_m() + h_ref));
  const Vec3 x0 = f.point(t, th);
  out = x0 + Vec3{x0.x * ia2, x0.y * ia2, x0.z * ib2}.normalized() * (h - h_ref);
  return true;
}

// The profile's ray look angle (ProfileSpan's, from the geodetic nadir) of
// the ground at height h and slant range r: the root of |X(th) - p| = r by
// bisection on [0, pi/2] (the range grows with th up to the horizon; a ray
// past it counts as infinitely far). 0 when r is shorter than the range
// straight down to h.
double ray_look_of_range(const ZeroDopplerFrame& f, const Ellipsoid& e, double h_ref, double h,
                         double r) {
  const auto range_at = [&](double th) {
    Vec3 x;
    return ground_at(f, e, h_ref, th, h, x) ? (x - f.sensor_m).norm()
                                            : std::numeric_limits<double>::infinity();
  };
  double lo = 0.0, hi = 0.5 * kPi;
  if (range_at(lo) >= r) return 0.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (range_at(mid) < r ? lo : hi) = mid;
  }
  return hi;
}

ProfileSpan AcquisitionRun::span_of_line(const ZeroDopplerFrame& f) const {
  const RadarGrid& g = acq.grid;
  const Ellipsoid& e = acq.ellipsoid;
  const double dr = g.range_spacing_m;
  // As ris topo: a margin for the terrain's relief (layover from beyond the
  // swath) and a few bins.
  const double margin = 2.0 * (dem_max_m - dem_min_m) + 4.0 * dr;
  const double r_near = g.range_of_bin(window.bin0);
  const double r_far = g.range_of_bin(window.bin0 + window.bins - 1);
  const double h_ref = 0.5 * (dem_min_m + dem_max_m);
  const Geodetic& sub = f.sensor_geodetic;
  const auto rho = [&](double h) { return e.to_ecef({sub.lat_rad, sub.lon_rad, h}).norm(); };
  // Look angles on the sphere through the highest (near) and lowest (far)
  // terrain, measured from the geocentric vertical; the profile's are from
  // the geodetic nadir, so the angle between the two widens the span too.
  const double look_near = f.look_on_sphere(r_near, rho(dem_max_m));
  const double look_far = f.look_on_sphere(r_far, rho(dem_min_m));
  const double tilt = std::acos(std::clamp(f.nadir.dot(f.sensor_m.normalized() * -1.0), -1.0, 1.0));
  const double pad = margin / r_near + tilt;
  // That span, widened to the ground that can fall in the swath's bins at
  // some height of the DEM where it misses it (relief large against the
  // swath: docs/geometry.md): the slant range grows with ground distance
  // and falls with height, so that ground runs from the near edge on the
  // lowest terrain to the far edge on the highest.
  ProfileSpan s;
  s.look_lo_rad = std::min(std::max(0.0, look_near - pad),
                           ray_look_of_range(f, e, h_ref, dem_min_m, r_near - 0.5 * dr));
  s.look_hi_rad =
      std::max(look_far + pad, ray_look_of_range(f, e, h_ref, dem_max_m, r_far + 0.5 * dr));
  // samples_per_bin points per range bin over the swath, as densely over
  // the pads: the swath's look angles between its near range on the
  // highest terrain and its far range on the lowest, which close up (and
  // cross) as the relief grows against the swath; so at most kMaxDensity
  // times as densely as over the swath at the DEM's mid height.
  const double swath_ref = f.look_on_sphere(r_far + 0.5 * dr, rho(h_ref)) -
                           f.look_on_sphere(r_near - 0.5 * dr, rho(h_ref));
  const double per_rad = (r_far - r_near + dr) / (dr / samples_per_bin) /
                         std::max(look_far - look_near, swath_ref / kMaxDensity);
  // Bounded before the cast (acquisition_max_points refuses more than
  // kMaxItems before anything is allocated).
  const double points =
      std::min((s.look_hi_rad - s.look_lo_rad) * per_rad + 2.0, static_cast<double>(kMaxItems));
  s.points = static_cast<std::size_t>(std::isfinite(points) ? std::max(points, 2.0) : 2.0);
  if (max_points > 0) s.points = std::min(s.points, max_points);
  s.height_ref_m = h_ref;
  return s;
}

std::size_t acquisition_max_points(AcquisitionRun& run) {
  run.max_points = 0;
  double n = 2.0;
  const GridWindow& w = run.window;
  for (int l : {w.line0, w.line0 + w.lines / 2, w.line0 + w.lines - 1}) {
    n = std::max(n, static_cast<double>(run.span_of_line(frame_of_line(run.acq, l)).points));
  }
  // Checked before the engine allocates them: the count, then each
  // thread's scratch.
  const std::string& file = run.dem.source;
  const std::string what = fmt::format(
      "terrain profile points a line ({}'s window of {} range bins of {} m at {} points a bin, "
      "over the DEM's heights {:.0f} to {:.0f} m: check those heights, an undeclared no-data "
      "value such as -32768 makes a huge relief, or crop the DEM to the radar grid's footprint)",
      run.acq.source, w.bins, run.acq.grid.range_spacing_m, run.samples_per_bin, run.dem_min_m,
      run.dem_max_m);
  const std::int64_t points =
      checked_count(n + std::floor(n / 4.0) + 16.0, kMaxItems - 1, file, "", what);
  const int threads = omp_get_max_threads();
  require_memory(
      checked_mul(checked_mul(points, kScratchBytesPerPoint, file, ""), threads, file, ""), file,
      "", fmt::format("{} x {} threads: {}", points, threads, what));
  return static_cast<std::size_t>(points);
}

DemRect dem_rect_of_lines(const AcquisitionRun& run, int line0, int line1) {
  const Ellipsoid& e = run.acq.ellipsoid;
  const EllipsoidalDem& dem = run.dem;
  constexpr std::size_t kEvery = 8;  // profile points between samples
  double r_lo = 1e300, r_hi = -1e300, c_lo = 1e300, c_hi = -1e300, gap = 0.0;
  for (int line = line0; line < line1; ++line) {
    const ZeroDopplerFrame f = frame_of_line(run.acq, run.window.line0 + line);
    const ProfileSpan span = run.span_of_line(f);
    const std::size_t n = span.points;
    // As trace_terrain_profile places its points on the reference ellipsoid.
    const double dlook = (span.look_hi_rad - span.look_lo_rad) / static_cast<double>(n - 1);
    double r_prev = kNan, c_prev = kNan;
    for (std::size_t k = 0; k < n; k = (k + 1 == n) ? n : std::min(k + kEvery, n - 1)) {
      const double th = span.look_lo_rad + static_cast<double>(k) * dlook;
      const double t = f.range_to_ellipsoid(th, e, span.height_ref_m);
      if (!std::isfinite(t)) continue;
      const Geodetic q = e.to_geodetic(f.point(t, th));
      const double r = (q.lat_rad - dem.lat0_rad) / dem.dlat_rad;
      const double c = (q.lon_rad - dem.lon0_rad) / dem.dlon_rad;
      r_lo = std::min(r_lo, r);
      r_hi = std::max(r_hi, r);
      c_lo = std::min(c_lo, c);
      c_hi = std::max(c_hi, c);
      if (std::isfinite(r_prev)) gap = std::max({gap, std::abs(r - r_prev), std::abs(c - c_prev)});
      r_prev = r;
      c_prev = c;
    }
  }
  if (r_lo > r_hi) return {};
  // The slope's neighbours (one posting), the bilinear cell (one), the
  // nearest posting and rounding (one), and the gaps between samples.
  const double m = 3.0 + std::ceil(gap);
  const double rows = dem.all_rows(), cols = dem.all_cols();
  const double a = std::clamp(std::floor(r_lo) - m, 0.0, rows);
  const double b = std::clamp(std::floor(r_hi) + 1.0 + m, -1.0, rows - 1.0);
  const double ca = std::clamp(std::floor(c_lo) - m, 0.0, cols);
  const double cb = std::clamp(std::floor(c_hi) + 1.0 + m, -1.0, cols - 1.0);
  if (b < a || cb < ca) return {};
  return {static_cast<int>(a), static_cast<int>(b - a) + 1, static_cast<int>(ca),
          static_cast<int>(cb - ca) + 1};
}

LineSpan AcquisitionLineSource::load(int line, LineScratch& s) {
  const RadarGrid& g = run.acq.grid;
  const Ellipsoid& e = run.acq.ellipsoid;
  const OrbitState st = run.acq.orbit.interpolate(g.time_of_line(run.window.line0 + line));
  const ZeroDopplerFrame f(st, g.look_side, e);
  const ProfileSpan span = run.span_of_line(f);
  trace_terrain_profile(f, e, run.dem, span, true, profile);
  const std::size_t n = span.points;
  look_rad.resize(n);
  range_m.resize(n);
  ground_u_m.resize(n);
  const Geodetic& sub = f.sensor_geodetic;
  const Vec3 nadir0 = e.to_ecef({sub.lat_rad, sub.lon_rad, 0.0});
  const double rho = nadir0.norm();
  const double sensor_h = sub.height_m;
  const bool flat = run.earth == EarthModel::flat;

  // The model's look angle and slant range, and the ground distance u from
  // the nadir along the ellipsoid (the chord's arc on the nadir's sphere).
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(profile.range_m[k])) {
      look_rad[k] = range_m[k] = ground_u_m[k] = kNan;
      continue;
    }
    const Vec3 foot = e.to_ecef({profile.lat_rad[k], profile.lon_rad[k], 0.0});
    const double chord = (foot - nadir0).norm();
    const double u = 2.0 * rho * std::asin(std::min(1.0, chord / (2.0 * rho)));
    ground_u_m[k] = u;
    if (flat) {
      const double dz = sensor_h - profile.height_m[k];
      range_m[k] = std::hypot(u, dz);
      look_rad[k] = std::atan2(u, dz);
    } else {
      range_m[k] = profile.range_m[k];
      look_rad[k] = profile.look_rad[k];
    }
  }
  mark_shadow_layover(n, look_rad.data(), range_m.data(), profile.flags.data());

  // The samples: ends halfway to the neighbours, area, angles, flags.
  const double az_per_radius = st.velocity_m_s.norm() * g.line_interval_s / st.position_m.norm();
  const auto ok = [&](std::size_t k) { return k < n && std::isfinite(range_m[k]); };
  for (std::size_t k = 0; k < n; ++k) {
    if (!ok(k)) {
      s.flags[k] = sample_flag::kNoData;
      s.height[k] = s.range[k] = s.near_end[k] = s.far_end[k] = s.incidence[k] =
          s.local_incidence[k] = s.area[k] = kNanF;
      s.category[k] = 0;
      continue;
    }
    const bool prev = k > 0 && ok(k - 1), next = ok(k + 1);
    const double r = range_m[k];
    const double r_prev = prev ? range_m[k - 1] : next ? 2.0 * r - range_m[k + 1] : r;
    const double r_next = next ? range_m[k + 1] : prev ? 2.0 * r - range_m[k - 1] : r;
    const double u = ground_u_m[k];
    const double du_prev = prev ? u - ground_u_m[k - 1] : next ? ground_u_m[k + 1] - u : 0.0;
    const double du_next = next ? ground_u_m[k + 1] - u : du_prev;
    const double lat = profile.lat_rad[k], lon = profile.lon_rad[k], h = profile.height_m[k];
    const Vec3& x = profile.ground_m[k];
    const DemSlope slope = dem_slope(run.dem, e, lat, lon, h);
    const double n_len = std::sqrt(1.0 + slope.east * slope.east + slope.north * slope.north);
    const EnuBasis b = Ellipsoid::enu(lat, lon);
    double cos_local = 0.0, incidence = 0.0;
    if (flat) {
      // The facet's slope along the ground look direction at the target.
      const Vec3 d = x - f.sensor_m;
      const double ce = d.dot(b.east), cn = d.dot(b.north), ch = std::hypot(ce, cn);
      const double g_look = ch > 0.0 ? (slope.east * ce + slope.north * cn) / ch : 0.0;
      cos_local = (u * g_look + (sensor_h - h)) / (r * n_len);
      incidence = look_rad[k];
    } else {
      const Vec3 l = (f.sensor_m - x) * (1.0 / profile.range_m[k]);
      const Vec3 normal = (b.east * -slope.east + b.north * -slope.north + b.up) * (1.0 / n_len);
      cos_local = normal.dot(l);
      incidence = std::acos(std::clamp(f.nadir_normal.dot(l), -1.0, 1.0));
    }
    std::uint8_t fl = 0;
    if (cos_local <= 0.0) fl |= sample_flag::kBackFacing;
    if (profile.flags[k] & kMaskShadow) fl |= sample_flag::kShadow;
    if (profile.flags[k] & kMaskLayover) fl |= sample_flag::kLayover;
    s.flags[k] = fl;
    s.height[k] = static_cast<float>(h);
    s.range[k] = static_cast<float>(r);
    s.near_end[k] = static_cast<float>(0.5 * (r + r_prev));
    s.far_end[k] = static_cast<float>(0.5 * (r + r_next));
    s.incidence[k] = static_cast<float>(incidence);
    s.local_incidence[k] = static_cast<float>(
        std::atan2(std::sqrt(std::max(0.0, 1.0 - cos_local * cos_local)), cos_local));
    s.area[k] =
        static_cast<float>(0.5 * std::abs(du_prev + du_next) * az_per_radius * x.norm() * n_len);
    s.category[k] = run.category_at(lat, lon);
  }
  return {0, static_cast<int>(n), run.layout};
}

void AcquisitionLineSource::store_maps(int line, const LineSpan& span, const LineScratch& s) {
  const RadarGrid& g = run.acq.grid;
  const GridWindow& w = run.window;
  const auto bins = static_cast<std::size_t>(w.bins);
  bin_count.assign(bins, 0);
  bin_shadow.assign(bins, 0);
  bin_layover.assign(bins, 0);
  bin_best.assign(bins, std::numeric_limits<float>::infinity());
  const auto row = static_cast<std::size_t>(line - run.maps_line0);
  float* local = run.local_incidence_deg + row * bins;
  std::uint8_t* mask = run.mask + row * bins;
  std::fill(local, local + bins, kNanF);
  std::fill(mask, mask + bins, std::uint8_t{kMaskNone});
  for (int k = 0; k < span.n; ++k) {
    const std::uint8_t fl = s.flags[static_cast<std::size_t>(k)];
    if (fl & sample_flag::kNoData) continue;
    const double at = g.bin_of_range(s.range[static_cast<std::size_t>(k)]) - w.bin0;
    const long b = std::lround(at);
    if (b < 0 || b >= w.bins) continue;
    const auto bb = static_cast<std::size_t>(b);
    ++bin_count[bb];
    bin_shadow[bb] += (fl & sample_flag::kShadow) != 0;
    bin_layover[bb] += (fl & sample_flag::kLayover) != 0;
    const auto off = static_cast<float>(std::abs(at - static_cast<double>(b)));
    if (off < bin_best[bb]) {
      bin_best[bb] = off;
      local[bb] = static_cast<float>(rad_to_deg(s.local_incidence[static_cast<std::size_t>(k)]));
    }
  }
  for (std::size_t b = 0; b < bins; ++b) {
    if (bin_count[b] == 0) continue;
    std::uint8_t m = kMaskNone;
    if (bin_shadow[b] == bin_count[b]) m |= kMaskShadow;
    if (bin_layover[b] > 0) m |= kMaskLayover;
    mask[b] = m;
  }
}

}  // namespace ris::detail
