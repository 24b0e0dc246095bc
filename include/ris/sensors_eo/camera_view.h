// The scene seen through a frame camera (issue 35 item 1; docs/sensors.md
// "Frame camera"): each pixel casts samples x samples rays through its
// area into the terrain mesh (Embree; buildings stand in the scene's grid as
// raised cells, so they occlude and are seen from the side as the grid's
// walls), and averages the scene-grid leaving radiance (ris/sensors_eo/
// eo_render.h, rendered without noise) of the cells the rays hit: the
// radiance integrated over the pixel's footprint. A Lambertian surface
// leaves the same radiance in every direction, so the grid's radiance is the
// radiance towards the camera. Thermal bands are averaged as radiance
// (Planck) and reported as brightness temperature. Then the optics' MTF
// (ris/sensors_eo/mtf_blur.h), then the noise: optical with a detector, the
// digital number (ris/sensors_eo/detector.h); otherwise Gaussian noise of
// the sensor's `noise` (radiance units, or K: the NETD). Noise is keyed on
// (seed, column, row, band), so bytes do not depend on the thread count.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ris/io/raster_io.h"
#include "ris/scene/scene.h"
#include "ris/sensors_eo/detector.h"
#include "ris/sensors_eo/eo_render.h"
#include "ris/sensors_eo/frame_camera.h"

namespace ris {

struct CameraImage {
  int rows = 0;
  int cols = 0;
  std::vector<std::string> band_names;
  std::vector<std::vector<float>> bands;  // NaN where no ray met the scene
  std::string unit;
  std::vector<std::vector<std::uint16_t>> digital_numbers;  // with a detector
  std::vector<float> range_m;                               // along the centre ray; NaN: none
  std::vector<float> footprint_area_m2;  // R^2 Omega / cos(incidence on the facet)
  std::vector<GroundControlPoint> gcps;  // pixel -> scene x, y, z (up to 16 x 16)
  std::int64_t empty_pixels = 0;         // no ray met the scene
};

// Rays a camera casts: samples^2 per pixel, plus the centre ray (range and
// footprint) when samples is even (when odd, the middle sample is it).
std::int64_t camera_ray_count(const FrameCamera& camera);

// Most pixels x rays a camera may cast (1e9: about a minute on two cores).
inline constexpr std::int64_t kMaxCameraRays = 1'000'000'000;

// grid: the scene-grid image without noise (render_eo with noise 0).
// Throws InputError naming camera.altitude for a camera at or below the
// terrain under it, camera.heading for one that sees none of the scene.
// terrain: the scene's (built here when not given).
CameraImage view_through_camera(const Scene& scene, const EoImage& grid,
                                const EoSensorConfig& sensor, const FrameCamera& camera,
                                const std::optional<Detector>& detector,
                                const EoTerrain* terrain = nullptr);

}  // namespace ris
