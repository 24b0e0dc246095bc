// An optical or thermal image on the scene grid: one pixel per scene cell,
// with the scene's geotransform and CRS, so that it overlays the radar's
// scene-grid products. Optical: band-mean radiance [W m^-2 sr^-1 um^-1] of a
// Lambertian surface (ris/sensors_eo/lambertian.h) with terrain slope and
// cast shadows from a ray to the sun through the terrain mesh
// (ris/sensors_eo/sun_shadow.h). Thermal: brightness temperature [K] of the
// diurnal surface temperature (ris/sensors_eo/diurnal_temperature.h) seen
// through the emissivity. Every pixel is independent and its noise is drawn
// from a counter-based generator keyed on (seed, column, row, band), so the
// bytes are the same for any thread count. docs/sensors.md.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ris/objects/mesh.h"
#include "ris/objects/sbr.h"
#include "ris/scene/scene.h"
#include "ris/sensors_eo/eo_sensor_config.h"
#include "ris/sensors_eo/sun_position.h"
#include "ris/sensors_eo/surface_table.h"

namespace ris {

struct EoImage {
  int rows = 0;
  int cols = 0;
  std::vector<std::string> band_names;
  std::vector<std::vector<float>> bands;  // rows*cols each; NaN off the scene's data
  std::string unit;                       // "W m-2 sr-1 um-1" or "K"
  SunPosition sun;
  double latitude_deg = 0;
  double longitude_deg = 0;
  bool night = false;  // sun at or below the horizon
  std::int64_t shadowed_cells = 0;
};

// The scene's terrain as a mesh: a vertex at each cell centre (local frame:
// world minus the grid's centre at height 0), two triangles per square of
// four valid cells.
TriangleMesh terrain_mesh(const Scene& scene);

// The terrain mesh's BVH, built once per scene and shared by the sun's rays
// and a camera's (building it is most of a small image's time). bvh is null
// for a scene without a square of four valid cells.
struct EoTerrain {
  std::unique_ptr<EmbreeScene> bvh;
  double top_z_m = 0;  // the highest vertex: rays to the sun stop above it
};
EoTerrain build_eo_terrain(const Scene& scene);

// Renders the image at the place (latitude, longitude of the scene's centre)
// with the scene's terrain (built here when not given). Throws InputError
// (naming the table) for a category the table lacks.
EoImage render_eo(const Scene& scene, const EoSensorConfig& sensor, const EoSurfaceTable& table,
                  double latitude_deg, double longitude_deg, const EoTerrain* terrain = nullptr);

}  // namespace ris
