// Object meshes from files through Assimp (OBJ, PLY, STL, glTF, ...), placed
// by position, rotation and scale (ris/objects/mesh.h's MeshPlacement).
//
// Refused, as InputError naming the file and what is wrong: a file that is not
// a regular file or cannot be read, one without triangles, a non-finite
// vertex, a degenerate triangle (zero area), more triangles than the cap.
//
// Example:
//   ris::TriangleMesh m = ris::load_mesh("tower.obj", {.scale = 0.01});
#pragma once

#include <cstddef>
#include <string>

#include "ris/objects/mesh.h"

namespace ris {

// The resource cap: 4 M triangles (about 200 MB of BVH in Embree).
constexpr std::size_t kMaxMeshTriangles = std::size_t{4} << 20;

TriangleMesh load_mesh(const std::string& path, const MeshPlacement& placement,
                       std::size_t max_triangles = kMaxMeshTriangles);

}  // namespace ris
