#include "ris/objects/mesh_load.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cmath>

#include <fmt/format.h>

#include "ris/io/safe_paths.h"
#include "ris/util/error.h"

namespace ris {
namespace {

void check_triangle(const TriangleMesh& m, const std::string& path, std::size_t index) {
  const auto& t = m.triangles[index];
  const Vec3 e1 = m.vertices[t[1]] - m.vertices[t[0]];
  const Vec3 e2 = m.vertices[t[2]] - m.vertices[t[0]];
  const double area2 = e1.cross(e2).norm();
  const double scale = std::max(e1.dot(e1), e2.dot(e2));
  if (!(area2 > 1e-12 * scale) || scale == 0.0) {
    throw InputError(path, "",
                     fmt::format("triangle {} is degenerate (zero area: repeated or collinear "
                                 "vertices); clean the mesh (e.g. merge by distance)",
                                 index));
  }
}

}  // namespace

TriangleMesh load_mesh(const std::string& path, const MeshPlacement& placement,
                       std::size_t max_triangles) {
  require_regular_input(path);
  Assimp::Importer importer;
  // Triangulate polygons, bake the node transforms into the vertices, and
  // sort primitives by type so that points and lines can be left out.
  const aiScene* scene = importer.ReadFile(
      path, aiProcess_Triangulate | aiProcess_PreTransformVertices | aiProcess_SortByPType);
  if (scene == nullptr || (scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0) {
    throw InputError(path, "",
                     std::string("cannot read the mesh: ") + importer.GetErrorString() +
                         " (expected OBJ, PLY, STL, glTF or another format Assimp reads)");
  }
  std::size_t count = 0;
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* mesh = scene->mMeshes[i];
    if ((mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) != 0) count += mesh->mNumFaces;
  }
  if (count == 0) throw InputError(path, "", "the mesh has no triangles");
  if (count > max_triangles) {
    throw InputError(path, "",
                     fmt::format("the mesh has {} triangles, more than the cap of {}; decimate it",
                                 count, max_triangles));
  }
  TriangleMesh out;
  out.triangles.reserve(count);
  for (unsigned i = 0; i < scene->mNumMeshes; ++i) {
    const aiMesh* mesh = scene->mMeshes[i];
    if ((mesh->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) == 0) continue;
    const auto base = static_cast<std::uint32_t>(out.vertices.size());
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
      const aiVector3D& p = mesh->mVertices[v];
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
        throw InputError(path, "", fmt::format("vertex {} of mesh {} is not finite", v, i));
      }
      out.vertices.push_back({p.x, p.y, p.z});
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f) {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3) continue;
      out.triangles.push_back(
          {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
      out.material.push_back(0);
      check_triangle(out, path, out.triangles.size() - 1);
    }
  }
  place(out, placement);
  return out;
}

}  // namespace ris
