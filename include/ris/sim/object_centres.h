// The scattering centres of a scene's cultural objects, as a SLAR/SAR track
// sees them (issue 32; docs/objects.md "Objects in a scene").
//
// Each object is lit by a plane wave from the radar at its broadside point
// (the track's point nearest its reference point), through one Embree BVH
// of every object and the ground around the buildings (ris/objects/
// object_scene.h), to 3 bounces. Every return of a ray tube is placed as
// Auer's RaySAR places it (Auer, Hinz & Bamler 2010, IEEE TGRS 48(4)): in
// slant range at half its two-way path, along the track at the mean of its
// first and last hits. The returns of one object that fall in one cell of
// (one line spacing along the track) x (one scene cell in slant range) are
// summed coherently, each with its phase exp(-j k L); the cell's |S_pq|^2
// for the radar's polarisation is the RCS of a point target placed at the
// cell's power-weighted mean along-track position and slant range, at the
// weighted mean of its returns' lowest hit (so a wall-ground double bounce
// sits at the wall's foot, where it images). The point targets then go
// through the line engine's scene-query stage as every point target does:
// lit or hidden by the terrain on their line, their power by the radar
// equation into their range bin. A reflector, smaller than a cell, is one
// centre: all its returns summed coherently.
//
// Paths that touch the ground alone are left out (the line engine images
// the terrain); a building is also painted into the grid, so its roof's
// diffuse return, its layover and its shadow come from the line engine.
//
// Example:
//   ris::ObjectCentreStats st;
//   std::vector<ris::PointTarget> c =
//       ris::object_scattering_centres(loaded.cultural_objects, loaded.scene, radar, &st);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "ris/scene/cultural_object.h"
#include "ris/scene/scene.h"
#include "ris/sensor/radar_params.h"
#include "ris/sim/point_target.h"

namespace ris {

struct ObjectCentreStats {
  std::int64_t objects = 0;
  std::int64_t triangles = 0;
  std::int64_t rays_launched = 0;
  std::int64_t rays_traced = 0;  // every segment: bounces and visibility rays
  std::int64_t returns = 0;
  std::int64_t centres = 0;
  std::int64_t behind_track = 0;  // objects not in front of the track (u <= 0): not traced
  std::vector<double> rcs_m2;     // per object: |sum of its centres' S|^2 for the polarisation
  double seconds = 0.0;
};

// Throws InputError for what build_object_scene refuses, and (naming
// radar.source_file) for a PPI or an ellipsoidal radar, whose geometry the
// centres do not follow yet.
std::vector<PointTarget> object_scattering_centres(const std::vector<CulturalObject>& objects,
                                                   const Scene& scene, const RadarParams& radar,
                                                   ObjectCentreStats* stats = nullptr);

// metadata.json's "objects": the counts above and each object's RCS (m^2, dBsm).
nlohmann::json object_centre_stats_json(const ObjectCentreStats& stats);

}  // namespace ris
