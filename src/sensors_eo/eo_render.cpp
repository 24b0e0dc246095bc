#include "ris/sensors_eo/eo_render.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "ris/objects/sbr.h"
#include "ris/sensors_eo/diurnal_temperature.h"
#include "ris/sensors_eo/facet_forcing.h"
#include "ris/sensors_eo/lambertian.h"
#include "ris/sensors_eo/planck_band.h"
#include "ris/sensors_eo/sun_shadow.h"
#include "ris/util/counter_rng.h"

namespace ris {
namespace {

constexpr std::uint32_t kEoNoiseStream = 0x454F4E00u;  // "EON\0"
constexpr float kNan = std::numeric_limits<float>::quiet_NaN();

Vec3 local_centre(const Scene& s, int row, int col) {
  const auto [x, y] = s.cell_centre(row, col);
  const auto [cx, cy] = s.world_from_grid(s.cols / 2.0, s.rows / 2.0);
  return {x - cx, y - cy, static_cast<double>(s.elevation_m[s.index(row, col)])};
}

// Unit upward normal from central differences (one-sided at the edges and
// next to no-data cells); y is north, rows run south.
Vec3 cell_normal(const Scene& s, int r, int c) {
  auto z = [&](int rr, int cc, double fallback) {
    if (rr < 0 || cc < 0 || rr >= s.rows || cc >= s.cols || !s.valid[s.index(rr, cc)])
      return fallback;
    return static_cast<double>(s.elevation_m[s.index(rr, cc)]);
  };
  const double z0 = s.elevation_m[s.index(r, c)];
  const double dzdx = (z(r, c + 1, z0) - z(r, c - 1, z0)) / (2 * s.dx_m);
  const double dzdy = (z(r - 1, c, z0) - z(r + 1, c, z0)) / (2 * s.dy_m);
  const double n = std::sqrt(dzdx * dzdx + dzdy * dzdy + 1);
  return {-dzdx / n, -dzdy / n, 1 / n};
}

double mesh_top_z(const TriangleMesh& m) {
  double top = -std::numeric_limits<double>::infinity();
  for (const Vec3& v : m.vertices) top = std::max(top, v.z);
  return top;
}

double add_noise(double v, const EoSensorConfig& cfg, int row, int col, std::size_t band) {
  if (cfg.noise <= 0) return v;
  CounterRng rng(cfg.seed, static_cast<std::uint32_t>(col), static_cast<std::uint32_t>(row),
                 kEoNoiseStream + static_cast<std::uint32_t>(band));
  return v + cfg.noise * rng.normal();
}

void render_optical(const Scene& scene, const EoSensorConfig& cfg, const EoSurfaceTable& table,
                    const EoTerrain& terrain, EoImage& img) {
  const double r2 = img.sun.earth_sun_distance_au * img.sun.earth_sun_distance_au;
  const double cos_z = std::cos(img.sun.zenith_deg * std::numbers::pi / 180.0);
  const Vec3 s = sun_direction_enu(img.sun.azimuth_deg, img.sun.elevation_deg);
  const EmbreeScene* bvh = terrain.bvh.get();
  const bool have_mesh = !img.night && bvh != nullptr;
  const double top = terrain.top_z_m;
  std::int64_t shadowed = 0;
#pragma omp parallel for schedule(dynamic, 8) reduction(+ : shadowed)
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      const std::size_t i = scene.index(r, c);
      if (!scene.valid[i]) continue;
      const EoSurface& surf = table.at(scene.category[i]);
      const Vec3 n = cell_normal(scene, r, c);
      const bool lit =
          !img.night && (!have_mesh || sun_visible(*bvh, local_centre(scene, r, c), s, 0.05, top));
      shadowed += (!img.night && !lit) ? 1 : 0;
      for (std::size_t b = 0; b < cfg.bands.size(); ++b) {
        const double e0 = eo_band_info(cfg.bands[b]).solar_irradiance_w_m2_um / r2;
        Illumination e;
        e.sun_irradiance_w_m2_um = img.night ? 0.0 : e0;
        e.cos_incidence = n.x * s.x + n.y * s.y + n.z * s.z;
        e.transmittance_down = cfg.transmittance;
        e.transmittance_up = cfg.transmittance;
        e.sky_irradiance_w_m2_um =
            img.night ? 0.0 : cfg.sky_fraction * e0 * cos_z * cfg.transmittance;
        e.path_radiance_w_m2_sr_um = cfg.path_radiance;
        e.lit = lit;
        img.bands[b][i] = static_cast<float>(
            add_noise(lambertian_radiance(band_property(surf, cfg.bands[b]), e), cfg, r, c, b));
      }
    }
  }
  img.shadowed_cells = shadowed;
}

// Each cell's surface temperature from its own day of insolation
// (ris/sensors_eo/facet_forcing.h): the sun on its facet's normal, and its
// cast shadows through the terrain mesh, at each of the day's samples; then
// the band brightness temperatures through the emissivity and the sky.
struct ThermalBands {
  std::vector<SpectralBand> ranges;
  std::vector<double> sky_radiance;  // per band, W m^-2 sr^-1
};

ThermalBands thermal_bands(const EoSensorConfig& cfg) {
  ThermalBands t;
  for (EoBand band : cfg.bands) {
    t.ranges.push_back(eo_band_info(band).range);
    t.sky_radiance.push_back(cfg.sky_temperature_k > 0
                                 ? planck_band_radiance(t.ranges.back(), cfg.sky_temperature_k)
                                 : 0.0);
  }
  return t;
}

// The insolation of the cell's facet at each sample (0 at night, on the
// facet's back or in a cast shadow).
void cell_insolation(const Scene& scene, const EmbreeScene* bvh, double top, const DaySamples& day,
                     int r, int c, std::vector<double>& out) {
  const Vec3 n = cell_normal(scene, r, c);
  const Vec3 p = local_centre(scene, r, c);
  for (std::size_t k = 0; k < day.t_seconds.size(); ++k) {
    const double cos_i = n.dot(day.sun_enu[k]);
    const bool up = day.irradiance_w_m2[k] > 0 && cos_i > 0;
    out[k] = up && (bvh == nullptr || sun_visible(*bvh, p, day.sun_enu[k], 0.05, top))
                 ? day.irradiance_w_m2[k] * cos_i
                 : 0.0;
  }
}

void render_thermal(const Scene& scene, const EoSensorConfig& cfg, const EoSurfaceTable& table,
                    const EoTerrain& terrain, EoImage& img) {
  const DaySamples day =
      day_samples(cfg.when, img.latitude_deg, img.longitude_deg, 8, cfg.transmittance);
  const double t_s = cfg.when.hour * 3600.0;
  const ThermalBands bands = thermal_bands(cfg);
  const EmbreeScene* bvh = terrain.bvh.get();
  const double top = terrain.top_z_m;
#pragma omp parallel
  {
    std::vector<double> insolation(day.t_seconds.size());  // once per thread
    DiurnalForcing f;
#pragma omp for schedule(dynamic, 8)
    for (int r = 0; r < scene.rows; ++r) {
      for (int c = 0; c < scene.cols; ++c) {
        const std::size_t i = scene.index(r, c);
        if (!scene.valid[i]) continue;
        const EoSurface& surf = table.at(scene.category[i]);
        cell_insolation(scene, bvh, top, day, r, c, insolation);
        forcing_from_insolation(day, insolation.data(), f);
        const ThermalSurface ts{cfg.mean_temperature_k, surf.thermal_inertia, surf.albedo,
                                surf.emissivity_lwir};
        const double temp = surface_temperature_k(ts, f, t_s);
        for (std::size_t b = 0; b < cfg.bands.size(); ++b) {
          const double l = thermal_leaving_radiance(band_property(surf, cfg.bands[b]),
                                                    planck_band_radiance(bands.ranges[b], temp),
                                                    bands.sky_radiance[b]);
          const double bt = l > 0 ? brightness_temperature_k(bands.ranges[b], l) : 0.0;
          img.bands[b][i] = static_cast<float>(add_noise(bt, cfg, r, c, b));
        }
      }
    }
  }
}

}  // namespace

TriangleMesh terrain_mesh(const Scene& scene) {
  TriangleMesh m;
  m.vertices.reserve(scene.size());
  for (int r = 0; r < scene.rows; ++r) {
    for (int c = 0; c < scene.cols; ++c) {
      m.vertices.push_back(scene.valid[scene.index(r, c)] ? local_centre(scene, r, c) : Vec3{});
    }
  }
  for (int r = 0; r + 1 < scene.rows; ++r) {
    for (int c = 0; c + 1 < scene.cols; ++c) {
      const auto a = static_cast<std::uint32_t>(scene.index(r, c));
      const auto b = static_cast<std::uint32_t>(scene.index(r, c + 1));
      const auto d = static_cast<std::uint32_t>(scene.index(r + 1, c));
      const auto e = static_cast<std::uint32_t>(scene.index(r + 1, c + 1));
      if (!scene.valid[a] || !scene.valid[b] || !scene.valid[d] || !scene.valid[e]) continue;
      m.triangles.push_back({a, d, e});
      m.triangles.push_back({a, e, b});
      m.material.push_back(0);
      m.material.push_back(0);
    }
  }
  return m;
}

EoTerrain build_eo_terrain(const Scene& scene) {
  EoTerrain t;
  const TriangleMesh mesh = terrain_mesh(scene);
  if (mesh.triangles.empty()) return t;
  t.top_z_m = mesh_top_z(mesh);
  t.bvh = std::make_unique<EmbreeScene>(mesh);
  return t;
}

EoImage render_eo(const Scene& scene, const EoSensorConfig& sensor, const EoSurfaceTable& table,
                  double latitude_deg, double longitude_deg, const EoTerrain* terrain) {
  EoImage img;
  img.rows = scene.rows;
  img.cols = scene.cols;
  img.latitude_deg = latitude_deg;
  img.longitude_deg = longitude_deg;
  img.sun = sun_position(sensor.when, latitude_deg, longitude_deg);
  img.night = img.sun.elevation_deg <= 0.0;
  img.unit = sensor.kind == EoKind::optical ? "W m-2 sr-1 um-1" : "K";
  for (EoBand b : sensor.bands) {
    img.band_names.emplace_back(eo_band_info(b).name);
    img.bands.emplace_back(scene.size(), kNan);
  }
  for (std::size_t i = 0; i < scene.size(); ++i) {  // fail before the parallel loops
    if (scene.valid[i]) table.at(scene.category[i]);
  }
  EoTerrain own;
  if (terrain == nullptr) {
    own = build_eo_terrain(scene);
    terrain = &own;
  }
  if (sensor.kind == EoKind::optical) {
    render_optical(scene, sensor, table, *terrain, img);
  } else {
    render_thermal(scene, sensor, table, *terrain, img);
  }
  return img;
}

}  // namespace ris
