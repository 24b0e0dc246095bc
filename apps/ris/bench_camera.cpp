#include "bench_camera.h"
#include "bench_timing.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "ris/scene/scene_source.h"
#include "ris/sensors_eo/camera_view.h"
#include "ris/sensors_eo/eo_render.h"

namespace ris::app {

void run_camera_bench(const std::string& data_dir, int repeats) {
  const LoadedScene town = load_scene_source(data_dir + "/scenes/town.toml");
  const EoSurfaceTable table = load_eo_surface_table(data_dir + "/sensors_eo/town-eo.csv");
  EoSensorConfig cfg = load_eo_sensor(data_dir + "/sensors_eo/optical-camera-town.toml");
  cfg.camera->samples = 1;
  cfg.camera->mtf_at_nyquist = 1.0;  // rays only: no blur
  cfg.detector.reset();
  const double lat = cfg.latitude_deg.value_or(48.1), lon = cfg.longitude_deg.value_or(11.6);
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(2);
  std::vector<double> build_s, grid_s, camera_s;
  EoImage grid;
  for (int i = 0; i < std::max(repeats, 1); ++i) {
    auto t0 = std::chrono::steady_clock::now();
    const EoTerrain terrain = build_eo_terrain(town.scene);
    build_s.push_back(seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    grid = render_eo(town.scene, cfg, table, lat, lon, &terrain);
    grid_s.push_back(seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    (void)view_through_camera(town.scene, grid, cfg, *cfg.camera, std::nullopt, &terrain);
    camera_s.push_back(seconds_since(t0));
  }
  omp_set_num_threads(threads_before);
  const double tb = median(build_s), tg = median(grid_s), tc = median(camera_s);
  const double cells = static_cast<double>(town.scene.size());
  const double rays = static_cast<double>(camera_ray_count(*cfg.camera));
  const double per_pixel = (tc + tg * rays / cells) / rays;  // one primary + one shadow ray
  fmt::print(
      "\nframe camera (data/scenes/town.toml, {} x {} pixels, 1 sample, 2 threads): terrain BVH "
      "{:.0f} ms ({:.1f} M triangles); grid sun rays {:.1f} M/s ({:.0f} ms for {:.0f} cells, "
      "shading included); camera rays {:.1f} M/s ({:.0f} ms, no MTF); a primary and a "
      "shadow ray per pixel: {:.1f} M pixels/s = {:.1f} M rays/s (goal 20 M rays/s)\n",
      cfg.camera->cols, cfg.camera->rows, 1e3 * tb, 2e-6 * cells, cells / tg * 1e-6, 1e3 * tg,
      cells, rays / tc * 1e-6, 1e3 * tc, 1e-6 / per_pixel, 2e-6 / per_pixel);
  fmt::print("camera_rays_per_s={:.0f}\n", rays / tc);
}

}  // namespace ris::app
