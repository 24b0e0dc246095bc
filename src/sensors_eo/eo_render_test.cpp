#include "ris/sensors_eo/eo_render.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>
#include <numbers>

#include "ris/sensors_eo/diurnal_temperature.h"
#include "ris/util/error.h"

namespace ris {
namespace {

const std::string kTable =
    "id,name,emissivity_lwir,emissivity_mwir,albedo,thermal_inertia,rho_blue,rho_green,rho_red,rho_"
    "nir\n"
    "21,grass,1.0,0.96,0.23,800,0.04,0.09,0.05,0.45\n"
    "24,urban,0.94,0.90,0.20,1683,0.15,0.16,0.17,0.20\n";

EoSensorConfig optical(double hour) {
  return parse_eo_sensor(
      "kind = \"optical\"\ndate = \"2024-06-21\"\ntime = \"" +
          std::to_string(static_cast<int>(hour)) +
          ":00:00\"\nbands = [\"red\", \"nir\"]\n[atmosphere]\ntransmittance = 0.8\n"
          "sky_fraction = 0.1\n",
      "s.toml");
}

// Flat ground, no shadow: every cell is rho (E0/r^2 cos z T^2 (1 + f)) / pi
// with f the sky fraction (sky = f E0 cos z T, seen through T).
TEST(EoRender, FlatOpticalIsLambertianUnderSunAndSky) {
  const Scene scene = Scene::flat(8, 8, 10.0, 100.0f, 21);
  const EoSurfaceTable table = parse_eo_surface_table(kTable, "t.csv");
  const EoSensorConfig cfg = optical(10);
  const EoImage img = render_eo(scene, cfg, table, 48.0, 11.0);
  ASSERT_FALSE(img.night);
  const double cz = std::cos(img.sun.zenith_deg * std::numbers::pi / 180.0);
  const double r2 = img.sun.earth_sun_distance_au * img.sun.earth_sun_distance_au;
  const double e0 = eo_band_info(EoBand::nir).solar_irradiance_w_m2_um / r2;
  const double expected = 0.45 * (e0 * cz * 0.8 + 0.1 * e0 * cz * 0.8) / std::numbers::pi * 0.8;
  for (float v : img.bands[1]) EXPECT_NEAR(v, expected, 1e-4 * expected);
  EXPECT_EQ(img.shadowed_cells, 0);
}

// A 30 m one-cell tower on flat ground shades the ground on its side away
// from the (eastern, morning) sun and not the side towards it. (The exact
// shadow length is checked on a box in sun_shadow_test.cpp; on the terrain
// mesh the tower's flanks slope over one cell.)
TEST(EoRender, TowerCastsShadowAwayFromTheSun) {
  Scene scene = Scene::flat(41, 41, 5.0, 0.0f, 21);
  scene.elevation_m[scene.index(20, 20)] = 30.0f;
  const EoSurfaceTable table = parse_eo_surface_table(kTable, "t.csv");
  const EoImage img = render_eo(scene, optical(8), table, 48.0, 11.0);  // morning sun in the east
  ASSERT_FALSE(img.night);
  EXPECT_GT(img.shadowed_cells, 0);
  EXPECT_LT(img.sun.azimuth_deg, 180.0);
  // The cell just west of the tower is darker than the one just east.
  EXPECT_LT(img.bands[0][scene.index(20, 18)], 0.5f * img.bands[0][scene.index(20, 22)]);
}

TEST(EoRender, NightOpticalIsPathRadianceOnly) {
  const Scene scene = Scene::flat(4, 4, 10.0, 0.0f, 21);
  const EoImage img =
      render_eo(scene, optical(0), parse_eo_surface_table(kTable, "t.csv"), 48.0, 11.0);
  EXPECT_TRUE(img.night);
  for (float v : img.bands[0]) EXPECT_EQ(v, 0.0f);
}

// Emissivity 1 and no sky: the brightness temperature is the model's
// surface temperature.
TEST(EoRender, ThermalBlackbodyShowsSurfaceTemperature) {
  const Scene scene = Scene::flat(4, 4, 10.0, 0.0f, 21);
  const EoSensorConfig cfg = parse_eo_sensor(
      "kind = \"thermal\"\ndate = \"2024-06-21\"\ntime = \"13:00:00\"\nbands = [\"lwir\"]\n",
      "s.toml");
  const EoImage img = render_eo(scene, cfg, parse_eo_surface_table(kTable, "t.csv"), 48.0, 11.0);
  const DiurnalForcing f = solar_forcing(cfg.when, 48.0, 11.0, 8, cfg.transmittance);
  const double t = surface_temperature_k({288.0, 800.0, 0.23, 1.0}, f, 13 * 3600.0);
  EXPECT_GT(t, 300.0);
  // Open flat ground: each cell's own forcing (30-minute samples, each its
  // interval's sun-up fraction) against solar_forcing's 1-minute samples:
  // 0.003 K apart.
  for (float v : img.bands[0]) EXPECT_NEAR(v, t, 0.01);
}

// Slopes and shadows heat as their own insolation says: at 13:00 UTC at
// 48 N (the sun in the south) a south-facing flank of a ridge is warmer than
// the north-facing one, and the ground in a tall wall's afternoon shadow (to
// its north-east) cooler than the open ground beside it.
TEST(EoRender, ThermalSlopesAndShadowsFollowTheSun) {
  Scene scene = Scene::flat(60, 60, 5.0, 0.0f, 21);
  for (int c = 0; c < 60; ++c) {
    for (int r = 10; r <= 20; ++r) {  // an east-west ridge, rows 10..20 (north at row 0)
      scene.elevation_m[scene.index(r, c)] = static_cast<float>(5 * (5 - std::abs(r - 15)));
    }
  }
  for (int r = 40; r < 42; ++r) {
    for (int c = 20; c < 22; ++c) scene.elevation_m[scene.index(r, c)] = 60.0f;  // a tower
  }
  const EoSensorConfig cfg = parse_eo_sensor(
      "kind = \"thermal\"\ndate = \"2024-06-21\"\ntime = \"13:00:00\"\nbands = [\"lwir\"]\n",
      "s.toml");
  const EoImage img = render_eo(scene, cfg, parse_eo_surface_table(kTable, "t.csv"), 48.0, 11.0);
  const std::vector<float>& t = img.bands[0];
  EXPECT_GT(t[scene.index(18, 30)], t[scene.index(12, 30)] + 2.0f);  // south flank vs north
  EXPECT_GT(t[scene.index(18, 30)], t[scene.index(50, 50)]);         // and vs flat ground
  EXPECT_LT(t[scene.index(12, 30)], t[scene.index(50, 50)]);
  // The tower's shadow at 13:00-16:00 UTC (sun south-west to west) lies to
  // its north-east; a cell there is cooler than open ground.
  EXPECT_LT(t[scene.index(37, 24)], t[scene.index(50, 50)] - 1.0f);
}

TEST(EoRender, SameBytesForAnyThreadCount) {
  Scene scene = Scene::flat(64, 64, 5.0, 0.0f, 21);
  for (std::size_t i = 0; i < scene.size(); i += 7) scene.category[i] = 24;
  scene.elevation_m[scene.index(30, 30)] = 20.0f;
  EoSensorConfig cfg = optical(9);
  cfg.noise = 0.5;
  const EoSurfaceTable table = parse_eo_surface_table(kTable, "t.csv");
  omp_set_num_threads(1);
  const EoImage one = render_eo(scene, cfg, table, 48.0, 11.0);
  omp_set_num_threads(2);
  const EoImage two = render_eo(scene, cfg, table, 48.0, 11.0);
  omp_set_num_threads(omp_get_num_procs());
  for (std::size_t b = 0; b < one.bands.size(); ++b) {
    EXPECT_EQ(
        std::memcmp(one.bands[b].data(), two.bands[b].data(), one.bands[b].size() * sizeof(float)),
        0);
  }
}

TEST(EoRender, SensorFileErrorsNameTheKey) {
  auto msg = [](const std::string& text) {
    try {
      parse_eo_sensor(text, "s.toml");
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string base = "date = \"2024-06-21\"\ntime = \"10:00:00\"\n";
  EXPECT_NE(msg("kind = \"optical\"\n" + base + "bands = [\"uv\"]\n").find("bands"),
            std::string::npos);
  EXPECT_NE(msg("kind = \"thermal\"\n" + base + "bands = [\"red\"]\n").find("optical"),
            std::string::npos);
  EXPECT_NE(msg("kind = \"radar\"\n" + base + "bands = [\"red\"]\n").find("kind"),
            std::string::npos);
  EXPECT_NE(
      msg("kind = \"optical\"\ndate = \"2024-13-01\"\ntime = \"10:00:00\"\nbands = [\"red\"]\n")
          .find("date"),
      std::string::npos);
  EXPECT_NE(
      msg("kind = \"optical\"\n" + base + "bands = [\"red\"]\n[atmosphere]\ntransmittance = 1.5\n")
          .find("atmosphere.transmittance"),
      std::string::npos);
}

TEST(EoRender, UnknownCategoryNamesTheTable) {
  const Scene scene = Scene::flat(4, 4, 10.0, 0.0f, 5);
  EXPECT_THROW(render_eo(scene, optical(10), parse_eo_surface_table(kTable, "t.csv"), 48.0, 11.0),
               InputError);
}

}  // namespace
}  // namespace ris
