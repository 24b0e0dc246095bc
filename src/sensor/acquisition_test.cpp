#include "ris/sensor/acquisition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "acquisition_paths.h"
#include "ris/sensor/generated_orbit.h"
#include "ris/sensor/sentinel1_annotation.h"
#include "ris/util/error.h"
#include "ris/util/units.h"
#include "test_util.h"

namespace ris {
namespace {

// Values from the product itself (gdalmdiminfo winnipeg.h5).
TEST(Acquisition, ReadsWinnipegNisarRslc) {
  const Acquisition a = read_acquisition(test::winnipeg_h5());
  EXPECT_EQ(a.format, "nisar-rslc");
  EXPECT_EQ(a.mission, "UAVSAR");
  EXPECT_EQ(a.polarisation, "HH");
  EXPECT_EQ(a.grid.lines, 250);
  EXPECT_EQ(a.grid.bins, 250);
  EXPECT_EQ(a.grid.look_side, LookSide::left);
  EXPECT_DOUBLE_EQ(a.grid.sensing_start_s, 172800.0);
  EXPECT_DOUBLE_EQ(a.grid.line_interval_s, 0.027329076);
  EXPECT_DOUBLE_EQ(a.grid.near_range_m, 13150.0574);
  EXPECT_DOUBLE_EQ(a.grid.range_spacing_m, 6.245676208);
  EXPECT_NEAR(a.grid.wavelength_m, kSpeedOfLight_m_per_s / 1.243e9, 1e-12);
  EXPECT_EQ(a.orbit.state_vectors().size(), 100U);
  EXPECT_EQ(a.orbit.epoch().iso(), "2012-07-15T14:36:47.000000");
  // Frequency B: same lines, its own range grid.
  AcquisitionOptions b;
  b.frequency = "B";
  const Acquisition ab = read_acquisition(test::winnipeg_h5(), b);
  EXPECT_EQ(ab.grid.bins, 660);
  EXPECT_DOUBLE_EQ(ab.grid.range_spacing_m, 24.98270483);
}

TEST(Acquisition, ReadsSanAndNisarRslc) {
  const Acquisition a = read_acquisition(test::sanand_h5());
  EXPECT_EQ(a.grid.lines, 150);
  EXPECT_EQ(a.grid.bins, 400);
  EXPECT_DOUBLE_EQ(a.grid.near_range_m, 16573.076404);
  EXPECT_EQ(a.grid.look_side, LookSide::left);
}

TEST(Acquisition, ReadsSentinel1Annotation) {
  const Acquisition a = read_acquisition(test::sentinel1_safe());
  EXPECT_EQ(a.mission, "S1A");
  EXPECT_EQ(a.polarisation, "VV");
  EXPECT_EQ(a.grid.look_side, LookSide::right);
  EXPECT_EQ(a.grid.bins, 22694);
  EXPECT_NEAR(a.grid.near_range_m, 5.336535882737799e-03 * kSpeedOfLight_m_per_s / 2, 1e-6);
  // rangePixelSpacing in the annotation: 2.329562 m.
  EXPECT_NEAR(a.grid.range_spacing_m, 2.329562, 1e-6);
  EXPECT_EQ(a.orbit.state_vectors().size(), 16U);
  // Debursted: first burst 17:05:58.268589 to the ninth's last line.
  const double span = 8 * 0.0 +
                      (parse_utc("2022-01-04T17:06:20.334986")
                           ->seconds_since(*parse_utc("2022-01-04T17:05:58.268589"))) +
                      1500 * 2.055556299999998e-03;
  EXPECT_EQ(a.grid.lines, static_cast<int>(std::lround(span / a.grid.line_interval_s)) + 1);
  AcquisitionOptions o;
  o.burst = 2;
  const Acquisition b2 = read_acquisition(test::sentinel1_safe(), o);
  EXPECT_EQ(b2.grid.lines, 1501);
  EXPECT_NEAR(b2.grid.sensing_start_s - a.grid.sensing_start_s,
              parse_utc("2022-01-04T17:06:03.785702")
                  ->seconds_since(*parse_utc("2022-01-04T17:05:58.268589")),
              1e-9);
  o.burst = 9;
  EXPECT_THROW(read_acquisition(test::sentinel1_safe(), o), InputError);
  EXPECT_EQ(read_sentinel1_tie_points(test::sentinel1_safe()).size(), 210U);
}

TEST(Acquisition, ReadsTomlExamples) {
  const Acquisition s = read_acquisition(test::example_acquisition("spaceborne-c-band-700km.toml"));
  EXPECT_EQ(s.grid.lines, 1000);
  EXPECT_EQ(s.grid.look_side, LookSide::right);
  // 700 km above the equatorial radius, on a circle.
  for (const StateVector& v : s.orbit.state_vectors()) {
    EXPECT_NEAR(v.position_m.norm(), 6378137.0 + 700e3, 1e-6);
  }
  const Acquisition f =
      read_acquisition(test::example_acquisition("airborne-l-band-flight-line.toml"));
  EXPECT_EQ(f.grid.look_side, LookSide::left);
  const OrbitState mid = f.orbit.interpolate(5.0);
  EXPECT_NEAR(mid.velocity_m_s.norm(), 220.0, 0.05);  // measured 0.01 (sphere vs ellipsoid)
  EXPECT_NEAR(f.ellipsoid.to_geodetic(mid.position_m).height_m, 12500.0, 1e-6);
}

TEST(Acquisition, TomlStateVectorsAndErrors) {
  test::TempDir tmp;
  const std::string head = R"([acquisition]
epoch = "2020-01-01T00:00:00"
look_side = "right"
wavelength = "0.0555 m"
[grid]
first_line_time = 1.0
line_interval = "1 ms"
lines = 10
near_range = "800 km"
range_spacing = 5.0
bins = 10
)";
  test::write_file(tmp / "sv.toml", head + R"([orbit]
kind = "state_vectors"
[[orbit.state_vector]]
time = 0.0
position = [7000000.0, 0.0, 0.0]
velocity = [0.0, 7500.0, 0.0]
[[orbit.state_vector]]
time = 10.0
position = [7000000.0, 75000.0, 0.0]
velocity = [0.0, 7500.0, 0.0]
)");
  const Acquisition a = read_acquisition(tmp / "sv.toml");
  EXPECT_NEAR(a.orbit.interpolate(5.0).position_m.y, 37500.0, 1e-9);
  // Enum values without regard to case, as a radar file's (issue 38).
  std::string mixed = test::read_file(tmp / "sv.toml");
  mixed.replace(mixed.find("\"right\""), 7, "\"Right\"");
  mixed.replace(mixed.find("\"state_vectors\""), 15, "\"State_Vectors\"");
  test::write_file(tmp / "mixed.toml", mixed);
  const Acquisition m = read_acquisition(tmp / "mixed.toml");
  EXPECT_EQ(m.grid.look_side, LookSide::right);
  EXPECT_EQ(m.orbit.interpolate(5.0).position_m.y, a.orbit.interpolate(5.0).position_m.y);
  // A misspelled key, a wrong look side, an orbit that does not cover the grid.
  test::write_file(tmp / "typo.toml", head +
                                          "[orbit]\nkind = \"circular\"\naltitude = 7e5\n"
                                          "inclination = 98\nascending_node_longitud = 3\n");
  try {
    read_acquisition(tmp / "typo.toml");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("ascending_node_longitude"), std::string::npos)
        << e.what();
  }
  test::write_file(tmp / "short.toml", head + R"([orbit]
kind = "state_vectors"
[[orbit.state_vector]]
time = 0.0
position = [7000000.0, 0.0, 0.0]
velocity = [0.0, 7500.0, 0.0]
[[orbit.state_vector]]
time = 0.5
position = [7000000.0, 3750.0, 0.0]
velocity = [0.0, 7500.0, 0.0]
)");
  EXPECT_THROW(read_acquisition(tmp / "short.toml"), InputError);
  EXPECT_THROW(read_acquisition(tmp / "missing.h5"), InputError);
  test::write_file(tmp / "x.csv", "1,2\n");
  EXPECT_THROW(read_acquisition(tmp / "x.csv"), InputError);
}

// Hermite interpolation of a circular orbit's 10-s vectors against the
// orbit itself every half second.
TEST(Orbit, HermiteReproducesACircularOrbit) {
  const Ellipsoid e = Ellipsoid::wgs84();
  CircularOrbitParams p;
  p.altitude_m = 700e3;
  p.inclination_rad = deg_to_rad(98.2);
  const UtcTime epoch{};
  const Orbit coarse = make_circular_orbit(p, e, epoch, 0.0, 200.0, 10.0);
  const Orbit fine = make_circular_orbit(p, e, epoch, 0.0, 200.0, 0.5);
  double worst_pos = 0.0, worst_vel = 0.0;
  for (const StateVector& s : fine.state_vectors()) {
    const OrbitState o = coarse.interpolate(s.time_s);
    worst_pos = std::max(worst_pos, (o.position_m - s.position_m).norm());
    worst_vel = std::max(worst_vel, (o.velocity_m_s - s.velocity_m_s).norm());
  }
  std::printf("Hermite: %.3g m, %.3g m/s\n", worst_pos, worst_vel);
  EXPECT_LT(worst_pos, 1e-3);  // measured 0.25 mm
  EXPECT_LT(worst_vel, 3e-4);  // measured 0.076 mm/s
}

}  // namespace
}  // namespace ris
