// Cast shadows: is a surface point lit by the sun? One occlusion ray per
// point towards the sun through an Embree scene (the terrain and objects
// mesh of ris/objects/object_scene.h, or any TriangleMesh). The sun is at
// infinity, so the ray's direction is the same everywhere:
//   s = (sin(az) cos(el), cos(az) cos(el), sin(el))  (x east, y north, z up).
// docs/sensors.md, "Shadows".
#pragma once

#include <limits>

#include "ris/objects/sbr.h"
#include "ris/util/vec3.h"

namespace ris {

// Unit vector towards the sun in the local east-north-up frame.
Vec3 sun_direction_enu(double azimuth_deg, double elevation_deg);

// True when the ray from p (lifted offset_m along the sun direction, so it
// does not hit its own facet) towards the sun meets no triangle. top_z_m:
// the highest vertex of the mesh, when known: the ray stops above it.
bool sun_visible(const EmbreeScene& scene, const Vec3& p, const Vec3& sun_dir,
                 double offset_m = 1e-3, double top_z_m = std::numeric_limits<double>::infinity());

}  // namespace ris
