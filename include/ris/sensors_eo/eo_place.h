// The place an optical or thermal image's sun is computed for: the sensor
// file's latitude/longitude when given, else the scene's centre through its
// CRS (docs/sensors.md, "Sensor file").
#pragma once

#include <string>
#include <utility>

#include "ris/scene/scene.h"
#include "ris/sensors_eo/eo_sensor_config.h"

namespace ris {

// {latitude, longitude} in degrees. Throws InputError naming the sensor
// file's `latitude` for a scene without a CRS and no place given.
std::pair<double, double> eo_place(const Scene& scene, const EoSensorConfig& cfg,
                                   const std::string& scene_path);

}  // namespace ris
