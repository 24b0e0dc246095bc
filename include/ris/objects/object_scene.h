// A scene's cultural objects (ris/scene/cultural_object.h) as one triangle
// mesh for one Embree BVH (issue 32; docs/objects.md "Objects in a scene"):
// each building's walls and flat roof, each reflector's exact mesh, and the
// terrain around the buildings (an apron of the grid's cells, so walls and
// ground make their double bounce). Part ids: 0 the ground, k + 1 object k.
//
// The mesh is in a local frame, world minus `origin_m` (the scene's centre
// at height 0): Embree works in float, and world coordinates of a projected
// CRS (5e6 m) would leave it half a metre of resolution.
//
// Example:
//   ris::ObjectSceneMesh m = ris::build_object_scene(objects, scene, library, 9.6e9);
//   ris::EmbreeScene bvh(m.mesh);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ris/objects/material.h"
#include "ris/objects/mesh.h"
#include "ris/objects/sbr.h"
#include "ris/scene/cultural_object.h"
#include "ris/scene/scene.h"
#include "ris/util/vec3.h"

namespace ris {

struct ObjectSceneMesh {
  TriangleMesh mesh;                      // local frame
  std::vector<SurfaceResponse> surfaces;  // by TriangleMesh::material
  std::vector<std::string> surface_names;
  Vec3 origin_m{};  // world position of the local frame's origin
  // Per object: its mesh's vertices (local frame; a launch window adds the
  // ground in front of it, which depends on the look), and its reference
  // point (a building's footprint centre at the foot, a reflector's origin).
  std::vector<std::vector<Vec3>> windows;
  std::vector<Vec3> centres_m;
  std::int64_t ground_triangles = 0;
};

// Most triangles a scene's objects may make (walls, roofs, reflectors and
// the ground apron): 16 M, about 1.3 GB of mesh and BVH.
inline constexpr std::int64_t kMaxObjectSceneTriangles = 16'000'000;

// Builds the mesh. The ground apron of a building reaches apron_factor x its
// height (at least two cells) beyond its footprint's bounds; under a
// footprint the ground is the building's base (the grid holds the painted
// roof there). Throws InputError naming the object's file and label: a
// material the library lacks or that is invalid at frequency_hz, a
// reflector off the scene or on no data, too many triangles.
ObjectSceneMesh build_object_scene(const std::vector<CulturalObject>& objects, const Scene& scene,
                                   const MaterialLibrary& library, double frequency_hz,
                                   double apron_factor = 3.0);

// A simple polygon's triangulation by ear clipping (counter-clockwise
// vertices): n - 2 triangles of vertex indices.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(
    const std::vector<std::array<double, 2>>& polygon);

}  // namespace ris
