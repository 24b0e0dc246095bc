#include "ris/geometry/zero_doppler.h"

#include <gtest/gtest.h>
#include <ogr_spatialref.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <random>

#include "acquisition_paths.h"
#include "ris/sensor/acquisition.h"
#include "ris/util/units.h"

namespace ris {
namespace {

// For random (line, bin, height) of an acquisition: the ground point by
// rdr2geo at that height, then geo2rdr from the grid's middle back to it.
// Doppler of the solution below 1e-6 of the PRF; rdr2geo(geo2rdr(p)) = p
// within 1 mm.
void round_trip(const Acquisition& acq, double h_min, double h_max) {
  const RadarGrid& g = acq.grid;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> line(0.0, g.lines - 1.0), bin(0.0, g.bins - 1.0),
      height(h_min, h_max);
  double worst_doppler = 0.0, worst_m = 0.0, worst_dt = 0.0, worst_dr = 0.0;
  for (int i = 0; i < 200; ++i) {
    const double l = line(rng), b = bin(rng), h = height(rng);
    const ZeroDopplerFrame f(acq.orbit.interpolate(g.time_of_line(l)), g.look_side, acq.ellipsoid);
    const auto flat = [h](double, double) { return h; };
    const GroundPoint p = rdr2geo(f, acq.ellipsoid, g.range_of_bin(b), flat, 0.0);
    ASSERT_TRUE(p.converged);
    const RadarPoint r = geo2rdr(acq.orbit, p.ecef_m, 0.5 * (g.sensing_start_s + g.end_s()));
    ASSERT_TRUE(r.converged);
    worst_doppler =
        std::max(worst_doppler,
                 std::abs(doppler_hz(acq.orbit, p.ecef_m, r.time_s, g.wavelength_m)) / g.prf_hz);
    worst_dt = std::max(worst_dt, std::abs(r.time_s - g.time_of_line(l)));
    worst_dr = std::max(worst_dr, std::abs(r.slant_range_m - g.range_of_bin(b)));
    const ZeroDopplerFrame f2(acq.orbit.interpolate(r.time_s), g.look_side, acq.ellipsoid);
    const GroundPoint back = rdr2geo(f2, acq.ellipsoid, r.slant_range_m, flat, 0.0);
    worst_m = std::max(worst_m, (back.ecef_m - p.ecef_m).norm());
  }
  std::printf("round trip: Doppler/PRF %.2g, |dX| %.2g m, |dt| %.2g s, |dR| %.2g m\n",
              worst_doppler, worst_m, worst_dt, worst_dr);
  // The limits; measured: Doppler 3.3e-11 of the PRF, 1.3e-8 m,
  // 5.8e-11 s, 2.9e-9 m (winnipeg, 700 km example, Sentinel-1 burst).
  EXPECT_LT(worst_doppler, 1e-6);
  EXPECT_LT(worst_m, 1e-3);
  EXPECT_LT(worst_dt, 1e-8);
  EXPECT_LT(worst_dr, 1e-6);
}

TEST(ZeroDoppler, RoundTripWinnipegAirborne) {
  round_trip(read_acquisition(test::winnipeg_h5()), 0.0, 3000.0);
}

TEST(ZeroDoppler, RoundTripSpaceborne) {
  round_trip(read_acquisition(test::example_acquisition("spaceborne-c-band-700km.toml")), -100.0,
             4000.0);
}

TEST(ZeroDoppler, RoundTripSentinel1) {
  AcquisitionOptions o;
  o.burst = 4;
  round_trip(read_acquisition(test::sentinel1_safe(), o), 0.0, 1500.0);
}

// Incidence against a computation that shares no geometry code with ris:
// the target's ECEF position and its ellipsoid normal from PROJ (EPSG:4979
// -> EPSG:4978; the normal is the direction in which the height moves the
// point), and the zero-Doppler time by bisection of v . (X - p) instead of
// Newton. Flat ground (constant height), airborne and spaceborne.
void incidence_against_proj(const Acquisition& acq, double h) {
  OGRSpatialReference geo, ecef;
  geo.importFromEPSG(4979);
  ecef.importFromEPSG(4978);
  geo.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  ecef.SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
  std::unique_ptr<OGRCoordinateTransformation> ct(OGRCreateCoordinateTransformation(&geo, &ecef));
  ASSERT_TRUE(ct);
  const RadarGrid& g = acq.grid;
  double worst = 0.0;
  for (double fl : {0.1, 0.5, 0.9}) {
    for (double fb : {0.0, 0.5, 1.0}) {
      // The ground point ris finds at (line, bin) on flat ground...
      const ZeroDopplerFrame f(acq.orbit.interpolate(g.time_of_line(fl * (g.lines - 1))),
                               g.look_side, acq.ellipsoid);
      const GroundPoint p = rdr2geo(
          f, acq.ellipsoid, g.range_of_bin(fb * (g.bins - 1)), [h](double, double) { return h; },
          h);
      ASSERT_TRUE(p.converged);
      const double lat = rad_to_deg(p.geodetic.lat_rad), lon = rad_to_deg(p.geodetic.lon_rad);
      // ... and its incidence from PROJ and bisection.
      double x[2] = {lon, lon}, y[2] = {lat, lat}, z[2] = {h, h + 1.0};
      ASSERT_TRUE(ct->Transform(2, x, y, z));
      const Vec3 target{x[0], y[0], z[0]};
      const Vec3 normal = Vec3{x[1] - x[0], y[1] - y[0], z[1] - z[0]}.normalized();
      double t0 = acq.orbit.start_s(), t1 = acq.orbit.end_s();
      const auto fd = [&](double t) {
        const OrbitState s = acq.orbit.interpolate(t);
        return s.velocity_m_s.dot(target - s.position_m);
      };
      for (int i = 0; i < 100; ++i) {
        const double tm = 0.5 * (t0 + t1);
        (fd(t0) > 0) == (fd(tm) > 0) ? t0 = tm : t1 = tm;
      }
      const Vec3 sensor = acq.orbit.interpolate(0.5 * (t0 + t1)).position_m;
      const double inc_proj = rad_to_deg(std::acos(normal.dot((sensor - target).normalized())));
      const RadarPoint r = geo2rdr(acq.orbit, p.ecef_m, g.sensing_start_s);
      const LookAngles a = look_angles(acq.ellipsoid, r.sensor_m, p.ecef_m);
      worst = std::max(worst, std::abs(a.incidence_deg - inc_proj));
    }
  }
  std::printf("incidence vs PROJ: %.2g deg\n", worst);
  EXPECT_LT(worst, 0.001);  // the limit; measured 2.3e-8 deg
}

TEST(ZeroDoppler, IncidenceAgainstProjAirborne) {
  incidence_against_proj(read_acquisition(test::winnipeg_h5()), 240.0);
  incidence_against_proj(
      read_acquisition(test::example_acquisition("airborne-l-band-flight-line.toml")), 230.0);
}

TEST(ZeroDoppler, IncidenceAgainstProjSpaceborne) {
  const Acquisition s = read_acquisition(test::example_acquisition("spaceborne-c-band-700km.toml"));
  incidence_against_proj(s, 0.0);
  // The example's grid spans the promised 30-45 deg.
  const RadarGrid& g = s.grid;
  const ZeroDopplerFrame f(s.orbit.interpolate(g.time_of_line(500)), g.look_side, s.ellipsoid);
  const auto zero = [](double, double) { return 0.0; };
  const GroundPoint near = rdr2geo(f, s.ellipsoid, g.near_range_m, zero, 0.0);
  const GroundPoint far = rdr2geo(f, s.ellipsoid, g.far_range_m(), zero, 0.0);
  const double inc_near = look_angles(s.ellipsoid, f.sensor_m, near.ecef_m).incidence_deg;
  const double inc_far = look_angles(s.ellipsoid, f.sensor_m, far.ecef_m).incidence_deg;
  EXPECT_GT(inc_near, 29.5);
  EXPECT_LT(inc_near, 31.0);
  EXPECT_GT(inc_far, 44.5);
  EXPECT_LT(inc_far, 46.0);
}

}  // namespace
}  // namespace ris
