#include "ris/sensors_eo/eo_place.h"

#include "ris/scene/geo_frame.h"
#include "ris/util/error.h"

namespace ris {

std::pair<double, double> eo_place(const Scene& scene, const EoSensorConfig& cfg,
                                   const std::string& scene_path) {
  if (cfg.latitude_deg && cfg.longitude_deg) return {*cfg.latitude_deg, *cfg.longitude_deg};
  if (scene.crs_wkt.empty()) {
    throw InputError(cfg.path, "latitude",
                     "the scene " + scene_path + " has no CRS: give latitude and longitude");
  }
  const GeoFrame frame(scene.crs_wkt, scene_path);
  const auto [x, y] = scene.world_from_grid(scene.cols / 2.0, scene.rows / 2.0);
  const auto [lon, lat] = frame.lonlat_from_scene(x, y);
  return {lat, lon};
}

}  // namespace ris
