#include "ris/geometry/topo.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <limits>

#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr float kNanF = std::numeric_limits<float>::quiet_NaN();
// Fixed-point unit of the DEM pass's sums: 2^-30 m^2 (int64 holds 8.6e9 m^2).
constexpr double kFixedPerM2 = 1073741824.0;
// geo2rdr's stopping step in the DEM pass (see the loop).
constexpr double kFacetTolerance_s = 1e-5;

double acos_deg(double c) {
  return rad_to_deg(std::acos(std::clamp(c, -1.0, 1.0)));
}

// Muhleman's law, MODEL.md section 4: 0.0118 cos t / (sin t + 0.111 cos t)^3.
double muhleman_sigma0(double cos_t) {
  const double s = std::sqrt(std::max(0.0, 1.0 - cos_t * cos_t));
  const double d = s + 0.111 * cos_t;
  return 0.0118 * cos_t / (d * d * d);
}

// CPU time of the whole process (all threads), for throughput figures that
// a busy machine does not distort.
double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double heading_deg_of(const Ellipsoid& e, const OrbitState& s) {
  const Geodetic g = e.to_geodetic(s.position_m);
  const EnuBasis b = Ellipsoid::enu(g.lat_rad, g.lon_rad);
  double h = rad_to_deg(std::atan2(s.velocity_m_s.dot(b.east), s.velocity_m_s.dot(b.north)));
  return h < 0.0 ? h + 360.0 : h;
}

// geo2rdr for the DEM pass: one Newton step on the orbit's cubic Hermite
// polynomial written, once per state-vector interval, in powers of
// s = (t - t_i) / h (p = P0 + P1 s + P2 s^2 + P3 s^3: the same cubic as
// Orbit::interpolate, so the same root up to rounding), with the interval
// found by one multiplication on evenly spaced state vectors. The facet loop
// makes no call; when the step is not below the tolerance (a poor guess,
// uneven state vectors, the orbit's ends) it hands over to geo2rdr.
class FacetLocator {
 public:
  FacetLocator(const Orbit& orbit, double tol_s) : orbit_(orbit), tol_s_(tol_s) {
    const auto& sv = orbit.state_vectors();
    const std::size_t n = sv.size();
    t0_ = sv.front().time_s;
    h_ = (sv.back().time_s - t0_) / static_cast<double>(n - 1);
    uniform_ = true;
    for (std::size_t i = 1; i < n; ++i) {
      if (std::abs(sv[i].time_s - sv[i - 1].time_s - h_) > 1e-9 * h_) uniform_ = false;
    }
    inv_h_ = 1.0 / h_;
    // Hermite basis expanded: P0 = p0, P1 = h v0, P2 = 3 (p1 - p0) - h (2 v0 + v1),
    // P3 = 2 (p0 - p1) + h (v0 + v1).
    for (std::size_t i = 0; i + 1 < n; ++i) {
      const StateVector& a = sv[i];
      const StateVector& b = sv[i + 1];
      Cubic c;
      c.p0 = a.position_m;
      c.p1 = a.velocity_m_s * h_;
      c.p2 = (b.position_m - a.position_m) * 3.0 - (a.velocity_m_s * 2.0 + b.velocity_m_s) * h_;
      c.p3 = (a.position_m - b.position_m) * 2.0 + (a.velocity_m_s + b.velocity_m_s) * h_;
      cubics_.push_back(c);
    }
  }

  RadarPoint locate(const Vec3& x, double t) const {
    const double u = (t - t0_) * inv_h_;
    if (!uniform_ || !(u >= 0.0) || u >= static_cast<double>(cubics_.size())) {
      return geo2rdr(orbit_, x, t, tol_s_);
    }
    const auto i = static_cast<std::size_t>(u);
    const Cubic& c = cubics_[i];
    const double s = u - static_cast<double>(i);
    const Vec3 p = ((c.p3 * s + c.p2) * s + c.p1) * s + c.p0;
    const Vec3 v = ((c.p3 * (3.0 * s) + c.p2 * 2.0) * s + c.p1) * inv_h_;
    const Vec3 acc = (c.p3 * (6.0 * s) + c.p2 * 2.0) * (inv_h_ * inv_h_);
    const Vec3 d = x - p;
    const double dt = -v.dot(d) / (acc.dot(d) - v.dot(v));
    if (!(std::abs(dt) < tol_s_)) return geo2rdr(orbit_, x, t + dt, tol_s_);
    RadarPoint r;
    r.time_s = t + dt;
    r.sensor_m = p + v * dt;
    r.slant_range_m = (x - r.sensor_m).norm();
    r.iterations = 1;
    r.converged = orbit_.covers(r.time_s);
    return r;
  }

 private:
  struct Cubic {
    Vec3 p0, p1, p2, p3;
  };
  const Orbit& orbit_;
  double tol_s_;
  double t0_ = 0.0, h_ = 1.0, inv_h_ = 1.0;
  bool uniform_ = false;
  std::vector<Cubic> cubics_;
};

}  // namespace

std::size_t topo_radar_line(const Acquisition& acq, const EllipsoidalDem& dem, const GridWindow& w,
                            int line, const TopoLineView& out, TopoLineScratch& sc) {
  const RadarGrid& g = acq.grid;
  const Ellipsoid& e = acq.ellipsoid;
  const OrbitState s = acq.orbit.interpolate(g.time_of_line(line));
  const ZeroDopplerFrame f(s, g.look_side, e);
  const float heading = static_cast<float>(heading_deg_of(e, s));
  const auto dem_h = [&dem](double la, double lo) { return dem.height_at(la, lo); };
  if (std::isnan(sc.dem_mean_height_m)) sc.dem_mean_height_m = dem.mean_height_m();
  double h_guess = sc.dem_mean_height_m;
  std::size_t bad = 0;
  double h_min = std::numeric_limits<double>::infinity(), h_max = -h_min;

  // rdr2geo of every bin on the DEM, each started from the look angle
  // extrapolated from the two bins before it.
  double look_last = kNan, look_step = 0.0;
  double look_min = std::numeric_limits<double>::infinity(), look_max = -look_min;
  int known = 0;
  for (int b = 0; b < w.bins; ++b) {
    const double r_m = g.range_of_bin(w.bin0 + b);
    const double look_guess = known == 0 ? kNan : known == 1 ? look_last : look_last + look_step;
    const GroundPoint p = rdr2geo(f, e, r_m, dem_h, h_guess, look_guess);
    if (p.converged) {
      look_min = std::min(look_min, p.look_rad);
      look_max = std::max(look_max, p.look_rad);
      look_step = p.look_rad - look_last;
      look_last = p.look_rad;
      known = std::min(known + 1, 2);
    } else {
      known = 0;
    }
    out.heading_deg[b] = heading;
    out.mask[b] = kMaskNone;
    if (!p.converged) {
      out.lat_deg[b] = out.lon_deg[b] = kNan;
      out.height_m[b] = out.incidence_deg[b] = out.incidence_geocentric_deg[b] =
          out.local_incidence_deg[b] = out.look_deg[b] = kNanF;
      ++bad;
      continue;
    }
    const Geodetic& q = p.geodetic;
    h_guess = q.height_m;
    h_min = std::min(h_min, q.height_m);
    h_max = std::max(h_max, q.height_m);
    const Vec3 los = (f.sensor_m - p.ecef_m) * (1.0 / r_m);  // target -> sensor
    out.lat_deg[b] = rad_to_deg(q.lat_rad);
    out.lon_deg[b] = rad_to_deg(q.lon_rad);
    out.height_m[b] = static_cast<float>(q.height_m);
    out.incidence_deg[b] =
        static_cast<float>(acos_deg(Ellipsoid::normal(q.lat_rad, q.lon_rad).dot(los)));
    out.incidence_geocentric_deg[b] = static_cast<float>(acos_deg(p.ecef_m.normalized().dot(los)));
    out.local_incidence_deg[b] =
        static_cast<float>(acos_deg(dem_normal(dem, e, q.lat_rad, q.lon_rad, q.height_m).dot(los)));
    out.look_deg[b] = static_cast<float>(acos_deg(f.nadir_normal.dot(los)));
  }
  if (bad == static_cast<std::size_t>(w.bins)) return bad;

  // Layover and shadow from a dense terrain profile in this line's
  // zero-Doppler plane (ris/geometry/terrain_profile.h, the profile the
  // simulation's acquisition line source images too): ground points at
  // evenly spaced look angles on the ellipsoid raised to the line's mid
  // height, moved onto the DEM, three per range bin on average, in ground
  // order; shadow and layover by its two scans.
  const double dr = g.range_spacing_m;
  const double margin = 2.0 * (h_max - h_min) + 4.0 * dr;
  const double h_ref = 0.5 * (h_min + h_max);
  const double r_near_bin = g.range_of_bin(w.bin0);
  const double r_near = r_near_bin - margin;
  const double r_far = g.range_of_bin(w.bin0 + w.bins - 1) + margin;
  // The look angles the line's ground spans, widened by the margin (as an
  // angle at the near range), from nadir at the least.
  const double look_pad = margin / r_near_bin;
  const double look_lo = std::max(0.0, look_min - look_pad);
  const double look_hi = look_max + look_pad;
  const auto n = static_cast<std::size_t>((r_far - r_near) / (dr / 3.0)) + 2;
  TerrainProfile& pr = sc.profile;
  trace_terrain_profile(f, e, dem, {look_lo, look_hi, n, h_ref}, false, pr);
  mark_shadow_layover(n, pr.look_rad.data(), pr.range_m.data(), pr.flags.data());
  // Into bins: layover when any ground in the bin is laid over, shadow when
  // all of it is shadowed.
  sc.count.assign(static_cast<std::size_t>(w.bins), 0);
  sc.shadowed.assign(static_cast<std::size_t>(w.bins), 0);
  sc.layover.assign(static_cast<std::size_t>(w.bins), 0);
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(pr.range_m[k])) continue;
    const long b = std::lround(g.bin_of_range(pr.range_m[k])) - w.bin0;
    if (b < 0 || b >= w.bins) continue;
    ++sc.count[b];
    sc.shadowed[b] += (pr.flags[k] & kMaskShadow) != 0;
    sc.layover[b] += (pr.flags[k] & kMaskLayover) != 0;
  }
  for (int b = 0; b < w.bins; ++b) {
    if (sc.count[b] == 0 || !std::isfinite(out.height_m[b])) continue;
    std::uint8_t m = kMaskNone;
    if (sc.shadowed[b] == sc.count[b]) m |= kMaskShadow;
    if (sc.layover[b] > 0) m |= kMaskLayover;
    out.mask[b] = m;
  }
  return bad;
}

LatLonBox grid_corner_box(const Acquisition& a, double height_m) {
  const RadarGrid& g = a.grid;
  const auto level = [height_m](double, double) { return height_m; };
  LatLonBox box{1e9, -1e9, 1e9, -1e9};
  for (double l : {0.0, g.lines - 1.0}) {
    for (double b : {0.0, g.bins - 1.0}) {
      const ZeroDopplerFrame f(a.orbit.interpolate(g.time_of_line(l)), g.look_side, a.ellipsoid);
      const GroundPoint p = rdr2geo(f, a.ellipsoid, g.range_of_bin(b), level, height_m);
      box.lat_min_rad = std::min(box.lat_min_rad, p.geodetic.lat_rad);
      box.lat_max_rad = std::max(box.lat_max_rad, p.geodetic.lat_rad);
      box.lon_min_rad = std::min(box.lon_min_rad, p.geodetic.lon_rad);
      box.lon_max_rad = std::max(box.lon_max_rad, p.geodetic.lon_rad);
    }
  }
  return box;
}

GridWindow dem_window(const Acquisition& acq, const EllipsoidalDem& dem) {
  float lo = std::numeric_limits<float>::infinity(), hi = -lo;
  for (float h : dem.height_m) {
    if (std::isfinite(h)) {
      lo = std::min(lo, h);
      hi = std::max(hi, h);
    }
  }
  if (!std::isfinite(lo)) return {};
  return dem_window(acq, dem, lo, hi);
}

GridWindow dem_window(const Acquisition& acq, const EllipsoidalDem& dem, float lo, float hi) {
  const RadarGrid& g = acq.grid;
  const Ellipsoid& e = acq.ellipsoid;
  if (!(std::isfinite(lo) && std::isfinite(hi))) return {};
  // The file's whole grid (a window's origin is the file's).
  const int rows = dem.all_rows(), cols = dem.all_cols();
  double l_min = 1e300, l_max = -1e300, b_min = 1e300, b_max = -1e300;
  const auto place = [&](int r, int c) {
    for (double h : {static_cast<double>(lo), static_cast<double>(hi)}) {
      const Vec3 x =
          e.to_ecef({dem.lat0_rad + r * dem.dlat_rad, dem.lon0_rad + c * dem.dlon_rad, h});
      const RadarPoint p = geo2rdr(acq.orbit, x, 0.5 * (g.sensing_start_s + g.end_s()));
      const double l = g.line_of_time(p.time_s), b = g.bin_of_range(p.slant_range_m);
      l_min = std::min(l_min, l);
      l_max = std::max(l_max, l);
      b_min = std::min(b_min, b);
      b_max = std::max(b_max, b);
    }
  };
  for (int c = 0; c < cols; ++c) {
    place(0, c);
    place(rows - 1, c);
  }
  for (int r = 0; r < rows; ++r) {
    place(r, 0);
    place(r, cols - 1);
  }
  GridWindow w;
  const double l0 = std::max(0.0, std::floor(l_min) - 2.0);
  const double l1 = std::min(g.lines - 1.0, std::ceil(l_max) + 2.0);
  const double b0 = std::max(0.0, std::floor(b_min) - 2.0);
  const double b1 = std::min(g.bins - 1.0, std::ceil(b_max) + 2.0);
  if (l1 < l0 || b1 < b0) return {};
  w.line0 = static_cast<int>(l0);
  w.lines = static_cast<int>(l1 - l0) + 1;
  w.bin0 = static_cast<int>(b0);
  w.bins = static_cast<int>(b1 - b0) + 1;
  return w;
}

namespace {

// The layers sized for the window; a window that would not fit in memory
// comfortably refused.
void allocate_topo_layers(const Acquisition& acq, const EllipsoidalDem& dem,
                          const TopoOptions& options, TopoLayers& t) {
  const GridWindow w = t.window;
  if (w.lines == 0 || w.bins == 0) {
    throw InputError(dem.source, "",
                     "the DEM does not cover any pixel of the acquisition's radar grid");
  }
  const std::size_t np = w.size();
  // Layers (53 bytes a pixel) and the DEM pass's sums (16 bytes a pixel per
  // thread) live in memory: refuse a window that would not fit comfortably.
  constexpr std::size_t kMaxPixels = 50'000'000;
  if (np > kMaxPixels) {
    throw InputError(
        acq.source, options.full_grid ? "--full-grid" : "--dem",
        fmt::format("the window is {} lines x {} bins ({:.0f} M pixels, about {:.1f} "
                    "GiB of layers); at most {} M pixels: choose one burst "
                    "(--burst), a smaller DEM, or drop --full-grid",
                    w.lines, w.bins, static_cast<double>(np) / 1e6,
                    static_cast<double>(np) * 90.0 / 1073741824.0, kMaxPixels / 1'000'000));
  }
  t.lat_deg.resize(np);
  t.lon_deg.resize(np);
  for (auto* v :
       {&t.height_m, &t.incidence_deg, &t.incidence_geocentric_deg, &t.local_incidence_deg,
        &t.look_deg, &t.heading_deg, &t.gamma_area_m2, &t.simulated_amplitude}) {
    v->resize(np);
  }
  t.mask.resize(np);
}

// Pass 1: the radar grid, line by line; returns the bins whose rdr2geo did
// not converge.
std::size_t radar_grid_pass(const Acquisition& acq, const EllipsoidalDem& dem, int threads,
                            TopoLayers& t) {
  const GridWindow w = t.window;
  std::size_t bad = 0;
#pragma omp parallel num_threads(threads) reduction(+ : bad)
  {
    TopoLineScratch sc;
#pragma omp for schedule(dynamic, 1)
    for (int l = 0; l < w.lines; ++l) {
      const std::size_t o = static_cast<std::size_t>(l) * w.bins;
      const TopoLineView v{t.lat_deg.data() + o,
                           t.lon_deg.data() + o,
                           t.height_m.data() + o,
                           t.incidence_deg.data() + o,
                           t.incidence_geocentric_deg.data() + o,
                           t.local_incidence_deg.data() + o,
                           t.look_deg.data() + o,
                           t.heading_deg.data() + o,
                           t.mask.data() + o};
      bad += topo_radar_line(acq, dem, w, w.line0 + l, v, sc);
    }
  }
  return bad;
}

// The DEM pass's extent: the DEM cells [r0, r1] x [c0, c1] under the
// window, each split into oversample^2 facets.
struct DemPassPlan {
  int r0 = 0, r1 = -1, c0 = 0, c1 = -1;
  int oversample = 1;
};

// The DEM cells under the window (its ground points' extent plus a margin
// for layover), and the facet size: below half a pixel on the ground. Sets
// t.oversample and t.beta_area_m2.
DemPassPlan plan_dem_pass(const Acquisition& acq, const EllipsoidalDem& dem,
                          const TopoOptions& options, TopoLayers& t) {
  const RadarGrid& g = acq.grid;
  const Ellipsoid& e = acq.ellipsoid;
  const GridWindow w = t.window;
  const std::size_t np = w.size();
  double la_min = 1e300, la_max = -1e300, lo_min = 1e300, lo_max = -1e300;
  double inc_sum = 0.0;
  std::size_t inc_n = 0;
  for (std::size_t i = 0; i < np; ++i) {
    if (!std::isfinite(t.lat_deg[i])) continue;
    la_min = std::min(la_min, t.lat_deg[i]);
    la_max = std::max(la_max, t.lat_deg[i]);
    lo_min = std::min(lo_min, t.lon_deg[i]);
    lo_max = std::max(lo_max, t.lon_deg[i]);
    inc_sum += t.incidence_deg[i];
    ++inc_n;
  }
  if (inc_n == 0) throw InputError(dem.source, "", "no pixel of the radar grid falls on the DEM");
  const double lat_mid = deg_to_rad(0.5 * (la_min + la_max));
  const OrbitState s_mid = acq.orbit.interpolate(g.time_of_line(w.line0 + 0.5 * (w.lines - 1)));
  const double rho_t = e.to_ecef({lat_mid, deg_to_rad(0.5 * (lo_min + lo_max)), 0.0}).norm();
  const double az_ground_m =
      s_mid.velocity_m_s.norm() * g.line_interval_s * rho_t / s_mid.position_m.norm();
  const double rg_ground_m =
      g.range_spacing_m / std::sin(deg_to_rad(inc_sum / static_cast<double>(inc_n)));
  const double dem_m =
      std::max(std::abs(dem.dlat_rad) * e.meridional_radius_m(lat_mid),
               std::abs(dem.dlon_rad) * e.prime_vertical_radius_m(lat_mid) * std::cos(lat_mid));
  t.oversample =
      options.oversample > 0
          ? options.oversample
          : std::clamp(
                static_cast<int>(std::ceil(2.0 * dem_m / std::min(az_ground_m, rg_ground_m))), 1,
                64);
  t.beta_area_m2 = g.range_spacing_m * az_ground_m;
  const auto row_of = [&](double lat_deg) {
    return (deg_to_rad(lat_deg) - dem.lat0_rad) / dem.dlat_rad;
  };
  const auto col_of = [&](double lon_deg) {
    return (deg_to_rad(lon_deg) - dem.lon0_rad) / dem.dlon_rad;
  };
  const int pad = 3;
  DemPassPlan p;
  p.oversample = t.oversample;
  p.r0 = std::max(0, static_cast<int>(std::floor(std::min(row_of(la_min), row_of(la_max)))) - pad);
  p.r1 = std::min(dem.rows - 2,
                  static_cast<int>(std::ceil(std::max(row_of(la_min), row_of(la_max)))) + pad);
  p.c0 = std::max(0, static_cast<int>(std::floor(std::min(col_of(lo_min), col_of(lo_max)))) - pad);
  p.c1 = std::min(dem.cols - 2,
                  static_cast<int>(std::ceil(std::max(col_of(lo_min), col_of(lo_max)))) + pad);
  return p;
}

// The DEM pass's per-facet-column constants: the DEM column, the bilinear
// weight, the longitude's cosine and sine (computed once for every facet
// row).
struct FacetColumns {
  std::vector<int> col_of_corner;
  std::vector<double> frac_of_corner, cos_lon, sin_lon;
  FacetColumns(const EllipsoidalDem& dem, const DemPassPlan& p, int nsub)
      : col_of_corner(static_cast<std::size_t>(nsub) + 1),
        frac_of_corner(col_of_corner.size()),
        cos_lon(col_of_corner.size()),
        sin_lon(col_of_corner.size()) {
    const int k = p.oversample;
    for (int j = 0; j <= nsub; ++j) {
      const double v = p.c0 + static_cast<double>(j) / k;
      col_of_corner[j] = std::min(static_cast<int>(v), dem.cols - 2);
      frac_of_corner[j] = v - col_of_corner[j];
      const double lon = dem.lon0_rad + v * dem.dlon_rad;
      cos_lon[j] = std::cos(lon);
      sin_lon[j] = std::sin(lon);
    }
  }
};

// Corner heights of facet row u: bilinear in the DEM cell; positions: the
// closed-form geodetic -> ECEF with the row's latitude terms computed once.
void facet_corner_row(const EllipsoidalDem& dem, const Ellipsoid& e, const FacetColumns& fc,
                      int nsub, double u, std::vector<Vec3>& out) {
  const int ru = std::min(static_cast<int>(u), dem.rows - 2);
  const double fu = u - ru;
  const double lat = dem.lat0_rad + u * dem.dlat_rad;
  const double sl = std::sin(lat), cl = std::cos(lat);
  const double nr = e.prime_vertical_radius_m(lat);
  for (int j = 0; j <= nsub; ++j) {
    const int cv = fc.col_of_corner[j];
    const double fv = fc.frac_of_corner[j];
    const double h = (dem.at(ru, cv) * (1.0 - fv) + dem.at(ru, cv + 1) * fv) * (1.0 - fu) +
                     (dem.at(ru + 1, cv) * (1.0 - fv) + dem.at(ru + 1, cv + 1) * fv) * fu;
    const double rc = (nr + h) * cl;
    out[j] = {rc * fc.cos_lon[j], rc * fc.sin_lon[j], (nr * (1.0 - e.e2()) + h) * sl};
  }
}

// What every facet of the DEM pass reads.
struct FacetPass {
  const GridWindow& w;
  const FacetLocator& locator;
  double orient;  // facet normals up
  double t_mid;   // the first guess of a row's first facet
  double inv_dt, inv_dr, line_origin, bin_origin;
};

// One facet row between corner rows `top` and `bottom` into the pixel sums
// (area and power side by side); returns the facets located.
std::size_t facet_row(const FacetPass& fp, int nsub, const std::vector<Vec3>& top,
                      const std::vector<Vec3>& bottom, std::vector<std::int64_t>& my_sums) {
  const GridWindow& w = fp.w;
  std::size_t facets = 0;
  // Warm start: the time extrapolated from the two previous facets
  // of the row (their times step almost evenly), so one Newton step
  // (one orbit interpolation) usually moves less than 1e-5 s, after
  // which the error left is of order 1e-13 s (Newton's quadratic
  // convergence), far below a line.
  double t_last = fp.t_mid, t_step = 0.0;
  int known = 0;
  for (int j = 0; j < nsub; ++j) {
    const Vec3 &a = top[j], &b = top[j + 1], &c = bottom[j], &d = bottom[j + 1];
    const Vec3 centre = (a + b + c + d) * 0.25;
    if (!std::isfinite(centre.x)) {
      known = 0;
      continue;
    }
    const double t_guess = known == 0 ? fp.t_mid : known == 1 ? t_last : t_last + t_step;
    const RadarPoint p = fp.locator.locate(centre, t_guess);
    if (!p.converged) {
      known = 0;
      continue;
    }
    t_step = p.time_s - t_last;
    t_last = p.time_s;
    known = std::min(known + 1, 2);
    ++facets;
    const Vec3 area = (d - a).cross(b - c) * (0.5 * fp.orient);
    const Vec3 los = (p.sensor_m - centre) * (1.0 / p.slant_range_m);
    const double proj = area.dot(los);
    if (proj <= 0.0) continue;  // facing away: no area, no echo
    const double a_m2 = area.norm();
    const double power = muhleman_sigma0(proj / a_m2) * a_m2;
    // Bilinear spread over the four nearest pixels.
    const double fl = (p.time_s - fp.line_origin) * fp.inv_dt;
    const double fb = (p.slant_range_m - fp.bin_origin) * fp.inv_dr;
    const double l0f = std::floor(fl), b0f = std::floor(fb);
    if (l0f < -1.0 || b0f < -1.0 || l0f >= w.lines || b0f >= w.bins) continue;
    const int l0 = static_cast<int>(l0f), b0 = static_cast<int>(b0f);
    const double wl = fl - l0f, wb = fb - b0f;
    const double wts[4] = {(1 - wl) * (1 - wb), (1 - wl) * wb, wl * (1 - wb), wl * wb};
    const int ls[4] = {l0, l0, l0 + 1, l0 + 1}, bs[4] = {b0, b0 + 1, b0, b0 + 1};
    for (int q = 0; q < 4; ++q) {
      if (ls[q] < 0 || ls[q] >= w.lines || bs[q] < 0 || bs[q] >= w.bins) continue;
      const std::size_t o = static_cast<std::size_t>(ls[q]) * w.bins + bs[q];
      // Round half up (values are >= 0): no library call per sample.
      my_sums[2 * o] += static_cast<std::int64_t>(proj * wts[q] * kFixedPerM2 + 0.5);
      my_sums[2 * o + 1] += static_cast<std::int64_t>(power * wts[q] * kFixedPerM2 + 0.5);
    }
  }
  return facets;
}

// Pass 2: every DEM facet into the radar grid: the pixels' area and power
// sums (fixed point, so that the sum does not depend on the threads), side
// by side (one cache line for both); returns the facets located.
std::size_t dem_facet_pass(const Acquisition& acq, const EllipsoidalDem& dem, const GridWindow& w,
                           const DemPassPlan& plan, int threads, std::vector<std::int64_t>& sums) {
  const RadarGrid& g = acq.grid;
  const Ellipsoid& e = acq.ellipsoid;
  const std::size_t np = w.size();
  const int k = plan.oversample;
  const int nsub = (plan.c1 - plan.c0 + 1) * k;  // facets per facet row
  const FacetColumns fc(dem, plan, nsub);
  const FacetLocator locator(acq.orbit, kFacetTolerance_s);
  const FacetPass fp{w, locator,
                     // Facet normals point up when rows run south and columns east.
                     (dem.dlat_rad < 0 ? 1.0 : -1.0) * (dem.dlon_rad > 0 ? 1.0 : -1.0),
                     g.time_of_line(w.line0 + 0.5 * (w.lines - 1)), 1.0 / g.line_interval_s,
                     1.0 / g.range_spacing_m, g.sensing_start_s + w.line0 * g.line_interval_s,
                     g.near_range_m + w.bin0 * g.range_spacing_m};
  sums.assign(2 * np, 0);
  std::size_t facets = 0;
#pragma omp parallel num_threads(threads) reduction(+ : facets)
  {
    std::vector<std::int64_t> my_sums(2 * np, 0);
    std::vector<Vec3> top(static_cast<std::size_t>(nsub) + 1), bottom(top.size());
#pragma omp for schedule(static)
    for (int r = plan.r0; r <= plan.r1; ++r) {
      facet_corner_row(dem, e, fc, nsub, r, bottom);
      for (int i = 0; i < k; ++i) {
        // This facet row's top corners are the last one's bottom corners.
        std::swap(top, bottom);
        facet_corner_row(dem, e, fc, nsub, r + static_cast<double>(i + 1) / k, bottom);
        facets += facet_row(fp, nsub, top, bottom, my_sums);
      }
    }
#pragma omp critical
    for (std::size_t i = 0; i < np; ++i) {
      sums[2 * i] += my_sums[2 * i];
      sums[2 * i + 1] += my_sums[2 * i + 1];
    }
  }
  return facets;
}

// The DEM pass's sums into the projected-area and amplitude layers.
void finish_topo_layers(const std::vector<std::int64_t>& sums, TopoLayers& t) {
  const std::size_t np = t.window.size();
  for (std::size_t i = 0; i < np; ++i) {
    const bool valid = std::isfinite(t.height_m[i]);
    t.gamma_area_m2[i] =
        valid ? static_cast<float>(static_cast<double>(sums[2 * i]) / kFixedPerM2) : kNanF;
    const double beta0 = static_cast<double>(sums[2 * i + 1]) / kFixedPerM2 / t.beta_area_m2;
    t.simulated_amplitude[i] = !valid ? kNanF
                               : (t.mask[i] & kMaskShadow) != 0
                                   ? 0.0F
                                   : static_cast<float>(std::sqrt(beta0));
  }
}

}  // namespace

TopoLayers compute_topo(const Acquisition& acq, const EllipsoidalDem& dem,
                        const TopoOptions& options) {
  const RadarGrid& g = acq.grid;
  TopoLayers t;
  t.window = options.full_grid ? GridWindow{0, g.lines, 0, g.bins} : dem_window(acq, dem);
  allocate_topo_layers(acq, dem, options, t);
  const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();

  const auto t0 = std::chrono::steady_clock::now();
  t.unconverged = radar_grid_pass(acq, dem, threads, t);
  const auto t1 = std::chrono::steady_clock::now();
  t.radar_seconds = std::chrono::duration<double>(t1 - t0).count();
  const double cpu1 = process_cpu_seconds();

  const DemPassPlan plan = plan_dem_pass(acq, dem, options, t);
  std::vector<std::int64_t> sums;
  t.dem_facets = dem_facet_pass(acq, dem, t.window, plan, threads, sums);
  t.dem_cells = static_cast<std::size_t>(plan.r1 - plan.r0 + 1) *
                static_cast<std::size_t>(plan.c1 - plan.c0 + 1);
  finish_topo_layers(sums, t);
  t.dem_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t1).count();
  t.dem_cpu_seconds = process_cpu_seconds() - cpu1;
  return t;
}

}  // namespace ris
