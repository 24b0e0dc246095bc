#include "ris/sensors_eo/camera_view.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "ris/objects/sbr.h"
#include "ris/sensors_eo/mtf_blur.h"
#include "ris/sensors_eo/planck_band.h"
#include "ris/util/counter_rng.h"
#include "ris/util/error.h"

namespace ris {
namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr std::uint32_t kCameraNoiseStream = 0x43414D00u;  // "CAM\0"
constexpr int kGcpsPerAxis = 16;
constexpr std::size_t kMaxBands = 8;  // more than EoBand has

struct Hit {
  bool ok = false;
  double t = 0;
  std::uint32_t prim = 0;
};

Hit first_hit(const EmbreeScene& bvh, const Vec3& org, const Vec3& dir) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRayHit rh{};
  rh.ray.org_x = static_cast<float>(org.x);
  rh.ray.org_y = static_cast<float>(org.y);
  rh.ray.org_z = static_cast<float>(org.z);
  rh.ray.dir_x = static_cast<float>(dir.x);
  rh.ray.dir_y = static_cast<float>(dir.y);
  rh.ray.dir_z = static_cast<float>(dir.z);
  rh.ray.tnear = 0.0f;
  rh.ray.tfar = std::numeric_limits<float>::infinity();
  rh.ray.mask = 0xFFFFFFFFu;
  rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(static_cast<RTCScene>(bvh.handle()), &ctx, &rh);
  if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return {};
  return {true, rh.ray.tfar, rh.hit.primID};
}

// What one pixel's rays see, before the MTF and the noise.
struct CameraSetup {
  const Scene* scene = nullptr;
  const EmbreeScene* bvh = nullptr;
  FrameCamera cam;
  CameraFrame frame;
  Vec3 eye;               // local frame (world minus the grid's centre at height 0)
  double cx = 0, cy = 0;  // the local frame's origin in scene x, y
  // Per band and category-free: the grid's radiance (thermal: converted back
  // from brightness temperature, so footprints average radiance).
  std::vector<std::vector<double>> grid_radiance;
};

// The scene cell under a local point, or -1 off the grid or on no data.
std::ptrdiff_t cell_of(const CameraSetup& s, const Vec3& p) {
  const auto [gc, gr] = s.scene->grid_from_world(p.x + s.cx, p.y + s.cy);
  const int c = static_cast<int>(std::floor(gc));
  const int r = static_cast<int>(std::floor(gr));
  if (r < 0 || c < 0 || r >= s.scene->rows || c >= s.scene->cols) return -1;
  const std::size_t i = s.scene->index(r, c);
  return s.scene->valid[i] ? static_cast<std::ptrdiff_t>(i) : -1;
}

void shade_pixel(const CameraSetup& s, int row, int col, CameraImage& img) {
  const std::size_t p = static_cast<std::size_t>(row) * img.cols + col;
  const int n = s.cam.samples;
  const std::size_t bands = s.grid_radiance.size();
  std::array<double, kMaxBands> sum{};  // no allocation per pixel
  int hits = 0;
  // The centre ray: range and footprint; with an odd number of samples it
  // is also the middle sub-sample (one ray, not two).
  const Vec3 dc = camera_ray_direction(s.frame, s.cam, row + 0.5, col + 0.5);
  const Hit hc = first_hit(*s.bvh, s.eye, dc);
  auto add = [&](const Vec3& d, const Hit& h) {
    if (!h.ok) return;
    const std::ptrdiff_t cell = cell_of(s, s.eye + d * h.t);
    if (cell < 0) return;
    ++hits;
    for (std::size_t k = 0; k < bands; ++k) sum[k] += s.grid_radiance[k][cell];
  };
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) {
      if (n % 2 == 1 && 2 * a + 1 == n && 2 * b + 1 == n) {
        add(dc, hc);
        continue;
      }
      const Vec3 d = camera_ray_direction(s.frame, s.cam, row + (a + 0.5) / n, col + (b + 0.5) / n);
      add(d, first_hit(*s.bvh, s.eye, d));
    }
  }
  for (std::size_t k = 0; k < bands; ++k) {
    img.bands[k][p] = hits > 0 ? static_cast<float>(sum[k] / hits) : kNan;
  }
  if (!hc.ok) return;
  const double cos_i = std::max(1e-3, std::abs(s.bvh->normals()[hc.prim].dot(dc)));
  img.range_m[p] = static_cast<float>(hc.t);
  img.footprint_area_m2[p] =
      static_cast<float>(hc.t * hc.t * pixel_solid_angle_sr(s.frame, dc) / cos_i);
}

CameraSetup make_setup(const Scene& scene, const EmbreeScene& bvh, const EoImage& grid,
                       const EoSensorConfig& sensor, const FrameCamera& cam) {
  CameraSetup s;
  s.scene = &scene;
  s.bvh = &bvh;
  s.cam = cam;
  s.frame = camera_frame(cam);
  std::tie(s.cx, s.cy) = scene.world_from_grid(scene.cols / 2.0, scene.rows / 2.0);
  s.eye = {cam.x_m - s.cx, cam.y_m - s.cy, cam.altitude_m};
  for (std::size_t k = 0; k < grid.bands.size(); ++k) {
    const SpectralBand range = eo_band_info(sensor.bands[k]).range;
    std::vector<double> v(grid.bands[k].begin(), grid.bands[k].end());
    if (sensor.kind == EoKind::thermal) {
      for (double& x : v) x = x > 0 ? planck_band_radiance(range, x) : 0.0;
    }
    s.grid_radiance.push_back(std::move(v));
  }
  return s;
}

void add_gcps(const CameraSetup& s, CameraImage& img) {
  const int nr = std::min(kGcpsPerAxis, img.rows), nc = std::min(kGcpsPerAxis, img.cols);
  for (int a = 0; a < nr; ++a) {
    for (int b = 0; b < nc; ++b) {
      const double line = nr == 1 ? 0.5 * img.rows : 0.5 + a * (img.rows - 1.0) / (nr - 1);
      const double pixel = nc == 1 ? 0.5 * img.cols : 0.5 + b * (img.cols - 1.0) / (nc - 1);
      const Vec3 d = camera_ray_direction(s.frame, s.cam, line, pixel);
      const Hit h = first_hit(*s.bvh, s.eye, d);
      if (!h.ok) continue;
      const Vec3 g = s.eye + d * h.t;
      img.gcps.push_back({pixel, line, g.x + s.cx, g.y + s.cy, g.z});
    }
  }
}

// Thermal: radiance back to brightness temperature; then the noise (or, for
// an optical camera with a detector, the digital numbers).
void finish_bands(const EoSensorConfig& sensor, const std::optional<Detector>& detector,
                  CameraImage& img) {
  const bool thermal = sensor.kind == EoKind::thermal;
  for (std::size_t k = 0; k < img.bands.size(); ++k) {
    const SpectralBand range = eo_band_info(sensor.bands[k]).range;
    std::vector<float>& band = img.bands[k];
    std::vector<std::uint16_t> dn(detector && !thermal ? band.size() : 0, 0);
#pragma omp parallel for schedule(static)
    for (int r = 0; r < img.rows; ++r) {
      for (int c = 0; c < img.cols; ++c) {
        const std::size_t p = static_cast<std::size_t>(r) * img.cols + c;
        if (!std::isfinite(band[p])) continue;
        if (thermal) {
          band[p] =
              band[p] > 0 ? static_cast<float>(brightness_temperature_k(range, band[p])) : 0.0f;
        }
        CounterRng rng(sensor.seed, static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(r),
                       kCameraNoiseStream + static_cast<std::uint32_t>(k));
        if (!dn.empty()) {
          dn[p] = digital_number(*detector, band[p], rng);
        } else if (sensor.noise > 0) {
          band[p] = static_cast<float>(band[p] + sensor.noise * rng.normal());
        }
      }
    }
    if (!dn.empty()) img.digital_numbers.push_back(std::move(dn));
  }
}

// A camera inside or under the terrain sees nothing the user meant.
void require_above_terrain(const Scene& scene, const EoSensorConfig& sensor,
                           const FrameCamera& cam) {
  const auto [gc, gr] = scene.grid_from_world(cam.x_m, cam.y_m);
  const int c = static_cast<int>(std::floor(gc)), r = static_cast<int>(std::floor(gr));
  if (r < 0 || c < 0 || r >= scene.rows || c >= scene.cols) return;
  const std::size_t i = scene.index(r, c);
  if (scene.valid[i] && cam.altitude_m <= scene.elevation_m[i]) {
    throw InputError(sensor.path, "camera.altitude",
                     "the camera (" + std::to_string(cam.altitude_m) +
                         " m) is at or below the terrain under it (" +
                         std::to_string(scene.elevation_m[i]) +
                         " m): give an altitude above the terrain (heights are above the "
                         "scene's datum, not above ground)");
  }
}

}  // namespace

std::int64_t camera_ray_count(const FrameCamera& cam) {
  const std::int64_t n = cam.samples;
  return static_cast<std::int64_t>(cam.cols) * cam.rows * (n * n + (n % 2 == 0 ? 1 : 0));
}

CameraImage view_through_camera(const Scene& scene, const EoImage& grid,
                                const EoSensorConfig& sensor, const FrameCamera& cam,
                                const std::optional<Detector>& detector, const EoTerrain* terrain) {
  CameraImage img;
  img.rows = cam.rows;
  img.cols = cam.cols;
  img.band_names = grid.band_names;
  img.unit = grid.unit;
  const std::size_t n = static_cast<std::size_t>(cam.rows) * cam.cols;
  img.bands.assign(grid.bands.size(), std::vector<float>(n, kNan));
  img.range_m.assign(n, kNan);
  img.footprint_area_m2.assign(n, kNan);
  require_above_terrain(scene, sensor, cam);
  EoTerrain own;
  if (terrain == nullptr) {
    own = build_eo_terrain(scene);
    terrain = &own;
  }
  if (!terrain->bvh) return img;
  const CameraSetup s = make_setup(scene, *terrain->bvh, grid, sensor, cam);
  std::int64_t empty = 0;
#pragma omp parallel for schedule(dynamic, 4) reduction(+ : empty)
  for (int r = 0; r < cam.rows; ++r) {
    for (int c = 0; c < cam.cols; ++c) {
      shade_pixel(s, r, c, img);
      const std::size_t p = static_cast<std::size_t>(r) * cam.cols + c;
      if (!std::isfinite(img.range_m[p])) ++empty;
    }
  }
  img.empty_pixels = empty;
  if (empty == static_cast<std::int64_t>(n)) {
    throw InputError(sensor.path, "camera.heading",
                     "the camera sees none of the scene (every ray misses it): turn it towards "
                     "the scene (camera.heading, clockwise from north; camera.depression, below "
                     "the horizontal) or move it (camera.position, scene metres)");
  }
  add_gcps(s, img);
  const double sigma = gaussian_sigma_px(cam.mtf_at_nyquist);
  for (std::vector<float>& band : img.bands) blur_gaussian_masked(band, img.rows, img.cols, sigma);
  finish_bands(sensor, detector, img);
  return img;
}

}  // namespace ris
