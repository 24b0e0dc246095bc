#include "ris/sensors_eo/sun_shadow.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <numbers>

namespace ris {

Vec3 sun_direction_enu(double azimuth_deg, double elevation_deg) {
  const double az = azimuth_deg * std::numbers::pi / 180.0;
  const double el = elevation_deg * std::numbers::pi / 180.0;
  return {std::sin(az) * std::cos(el), std::cos(az) * std::cos(el), std::sin(el)};
}

bool sun_visible(const EmbreeScene& scene, const Vec3& p, const Vec3& sun_dir, double offset_m,
                 double top_z_m) {
  // Above the top of the mesh the ray meets nothing: clip it there (a
  // grazing ray over flat ground would otherwise visit most of the BVH).
  float tfar = std::numeric_limits<float>::infinity();
  if (std::isfinite(top_z_m) && sun_dir.z > 0) {
    if (p.z >= top_z_m) return true;
    tfar = static_cast<float>((top_z_m - p.z) / sun_dir.z + 1.0);
  }
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay ray{};
  ray.org_x = static_cast<float>(p.x + offset_m * sun_dir.x);
  ray.org_y = static_cast<float>(p.y + offset_m * sun_dir.y);
  ray.org_z = static_cast<float>(p.z + offset_m * sun_dir.z);
  ray.dir_x = static_cast<float>(sun_dir.x);
  ray.dir_y = static_cast<float>(sun_dir.y);
  ray.dir_z = static_cast<float>(sun_dir.z);
  ray.tnear = 0.0f;
  ray.tfar = tfar;
  ray.mask = 0xFFFFFFFFu;
  rtcOccluded1(static_cast<RTCScene>(scene.handle()), &ctx, &ray);
  return ray.tfar >= 0.0f;  // Embree sets tfar to -inf when occluded
}

}  // namespace ris
