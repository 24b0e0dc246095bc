#include "ris/sensors_eo/camera_view.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "ris/sensors_eo/planck_band.h"
#include "ris/util/error.h"

namespace ris {
namespace {

const std::string kTable =
    "id,name,emissivity_lwir,emissivity_mwir,albedo,thermal_inertia,rho_blue,rho_green,rho_red,rho_"
    "nir\n"
    "21,grass,1.0,0.96,0.23,800,0.04,0.09,0.05,0.45\n"
    "24,urban,0.94,0.90,0.20,1683,0.15,0.16,0.17,0.20\n";

EoSensorConfig sensor(const std::string& kind, const std::string& bands, double noise = 0) {
  return parse_eo_sensor("kind = \"" + kind +
                             "\"\ndate = \"2024-06-21\"\ntime = \"10:00:00\"\nbands = [" + bands +
                             "]\nnoise = " + std::to_string(noise) + "\n",
                         "s.toml");
}

FrameCamera nadir(double x, double y, double altitude, int n) {
  FrameCamera c;
  c.x_m = x;
  c.y_m = y;
  c.altitude_m = altitude;
  c.depression_deg = 90;
  c.fov_deg = 20;
  c.cols = n;
  c.rows = n;
  c.samples = 2;
  return c;
}

// A 200 m x 200 m flat field, grass to the west of x = 100 m and urban to
// the east, at 10 m elevation.
Scene two_fields() {
  Scene s = Scene::flat(200, 200, 1.0, 10.0f, 21);
  for (int r = 0; r < s.rows; ++r) {
    for (int c = 100; c < s.cols; ++c) s.category[s.index(r, c)] = 24;
  }
  return s;
}

// Nadir over flat ground: a central projection onto a parallel plane is a
// uniform scale, so every pixel's footprint is (H / f)^2 and its ground
// point lies (col + 0.5 - cols / 2) H / f east of the nadir; each half of
// the picture shows its own field's radiance.
TEST(CameraView, NadirOverFlatGroundHasTheClosedFormFootprints) {
  const Scene scene = two_fields();
  const EoSurfaceTable table = parse_eo_surface_table(kTable, "t.csv");
  const EoSensorConfig cfg = sensor("optical", "\"red\", \"nir\"");
  const EoImage grid = render_eo(scene, cfg, table, 48.0, 11.0);
  const FrameCamera cam = nadir(100.0, 100.0, 110.0, 64);  // 100 m above the ground
  const CameraImage img = view_through_camera(scene, grid, cfg, cam, std::nullopt);
  const CameraFrame f = camera_frame(cam);
  const double gsd = 100.0 / f.focal_px;
  EXPECT_EQ(img.empty_pixels, 0);
  for (std::size_t p = 0; p < img.footprint_area_m2.size(); ++p) {
    ASSERT_NEAR(img.footprint_area_m2[p], gsd * gsd, 1e-4 * gsd * gsd);
  }
  const std::size_t centre = 31 * 64 + 31;  // pixel centre 0.5 px from the axis each way
  EXPECT_NEAR(img.range_m[centre], std::hypot(100.0, 0.5 * gsd, 0.5 * gsd), 1e-3);
  ASSERT_EQ(img.gcps.size(), 256u);
  for (const GroundControlPoint& g : img.gcps) {
    EXPECT_NEAR(g.x, 100.0 + (g.pixel - 32.0) * gsd, 1e-3);
    EXPECT_NEAR(g.y, 100.0 - (g.line - 32.0) * gsd, 1e-3);
    EXPECT_NEAR(g.z, 10.0, 1e-3);
  }
  const float grass = grid.bands[1][scene.index(100, 10)];
  const float urban = grid.bands[1][scene.index(100, 190)];
  for (int r = 0; r < 64; ++r) {
    EXPECT_FLOAT_EQ(img.bands[1][static_cast<std::size_t>(r) * 64 + 5], grass);
    EXPECT_FLOAT_EQ(img.bands[1][static_cast<std::size_t>(r) * 64 + 58], urban);
  }
}

// Oblique: 45 deg below the horizontal, the axis meets flat ground at
// H / sin 45 and the footprint there is R^2 / f^2 / cos 45.
TEST(CameraView, ObliqueCentreRangeAndFootprint) {
  const Scene scene = two_fields();
  const EoSurfaceTable table = parse_eo_surface_table(kTable, "t.csv");
  const EoSensorConfig cfg = sensor("optical", "\"red\"");
  const EoImage grid = render_eo(scene, cfg, table, 48.0, 11.0);
  FrameCamera cam = nadir(40.0, 100.0, 60.0, 2);  // 50 m above the ground
  cam.heading_deg = 90;
  cam.depression_deg = 45;
  cam.fov_deg = 0.002;
  const CameraImage img = view_through_camera(scene, grid, cfg, cam, std::nullopt);
  const double r = 50.0 / std::sin(std::numbers::pi / 4);
  const double f = camera_frame(cam).focal_px;
  EXPECT_NEAR(img.range_m[0], r, 1e-3);
  EXPECT_NEAR(img.footprint_area_m2[0], r * r / (f * f) / std::cos(std::numbers::pi / 4),
              1e-3 * r * r / (f * f));
}

// Looking east along the horizontal at 10 m, the ray meets a 20 m block
// whose mesh rises from the cell centre at x = 119.5 to the one at 120.5:
// at height 10 m, x = 120 (70 m from the camera at x = 50).
TEST(CameraView, ABlockOccludesTheGroundBehindIt) {
  Scene scene = Scene::flat(200, 200, 1.0, 0.0f, 21);
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 120; c < 130; ++c) scene.elevation_m[scene.index(r, c)] = 20.0f;
  }
  const EoSurfaceTable table = parse_eo_surface_table(kTable, "t.csv");
  const EoSensorConfig cfg = sensor("optical", "\"red\"");
  const EoImage grid = render_eo(scene, cfg, table, 48.0, 11.0);
  FrameCamera cam = nadir(50.0, 100.5, 10.0, 2);
  cam.heading_deg = 90;
  cam.depression_deg = 0;
  cam.fov_deg = 0.01;
  const CameraImage img = view_through_camera(scene, grid, cfg, cam, std::nullopt);
  EXPECT_NEAR(img.range_m[0], 70.0, 1e-2);
}

// A thermal camera averages radiance and reports brightness temperature:
// over one uniform field it reads the grid's temperature (through Planck and
// back) whatever the MTF; a camera that sees none of the scene, or stands
// under its terrain, is refused naming the key.
TEST(CameraView, ThermalReadsTheGridTemperatureAndSkyIsEmpty) {
  const Scene scene = Scene::flat(100, 100, 1.0, 0.0f, 21);
  const EoSurfaceTable table = parse_eo_surface_table(kTable, "t.csv");
  const EoSensorConfig cfg = sensor("thermal", "\"lwir\"");
  const EoImage grid = render_eo(scene, cfg, table, 48.0, 11.0);
  FrameCamera cam = nadir(50.0, 50.0, 200.0, 16);
  cam.fov_deg = 10;
  cam.mtf_at_nyquist = 0.2;
  const CameraImage img = view_through_camera(scene, grid, cfg, cam, std::nullopt);
  const float t = grid.bands[0][0];
  for (float v : img.bands[0]) EXPECT_NEAR(v, t, 1e-3f);
  cam.depression_deg = 0;  // the horizon: the ground it could see lies km off the scene
  cam.altitude_m = 1000.0;
  try {
    (void)view_through_camera(scene, grid, cfg, cam, std::nullopt);
    ADD_FAILURE() << "a camera that sees none of the scene was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("camera.heading"), std::string::npos) << e.what();
  }
  cam.depression_deg = 90;
  cam.altitude_m = -5.0;  // under the ground (0 m)
  try {
    (void)view_through_camera(scene, grid, cfg, cam, std::nullopt);
    ADD_FAILURE() << "a camera under the terrain was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("camera.altitude"), std::string::npos) << e.what();
  }
}

// Noise keyed on pixel and band: the same bytes for one and two threads.
TEST(CameraView, SameBytesForOneAndTwoThreads) {
  const Scene scene = two_fields();
  const EoSurfaceTable table = parse_eo_surface_table(kTable, "t.csv");
  const EoSensorConfig cfg = sensor("optical", "\"red\", \"nir\"", 0.5);
  EoSensorConfig quiet = cfg;
  quiet.noise = 0;
  const EoImage grid = render_eo(scene, quiet, table, 48.0, 11.0);
  FrameCamera cam = nadir(100.0, 100.0, 110.0, 48);
  cam.mtf_at_nyquist = 0.3;
  const Detector det{100.0, 10.0, 20000.0, 12};
  std::vector<CameraImage> runs;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    runs.push_back(view_through_camera(scene, grid, cfg, cam, det));
  }
  omp_set_num_threads(omp_get_num_procs());
  ASSERT_EQ(runs[0].digital_numbers.size(), 2u);
  EXPECT_EQ(runs[0].digital_numbers, runs[1].digital_numbers);
  EXPECT_EQ(0, std::memcmp(runs[0].bands[0].data(), runs[1].bands[0].data(),
                           runs[0].bands[0].size() * sizeof(float)));
}

}  // namespace
}  // namespace ris
