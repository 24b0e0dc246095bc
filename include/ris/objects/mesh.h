// Triangle meshes of cultural objects: the canonical reflectors (exact
// meshes of flat plates; tessellated sphere and cylinder) and placement
// (scale, rotation, translation). Every canonical reflector is built with its
// boresight along +x (docs/objects.md), so a radar at azimuth 0, elevation 0
// looks at it along its boresight.
//
// Example:
//   ris::TriangleMesh m = ris::make_trihedral_square(0.5);
//   ris::place(m, {.azimuth_rad = 0.3});
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "ris/util/vec3.h"

namespace ris {

struct TriangleMesh {
  std::vector<Vec3> vertices;  // metres
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<std::uint32_t> material;  // per triangle: index into a material list
  // Per triangle, optional (empty: every triangle part 0): which object it
  // belongs to, 0 for the ground around objects (ris/objects/object_scene.h).
  std::vector<std::uint32_t> part;

  void add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, std::uint32_t mat = 0);
  // Two triangles a-b-c, a-c-d.
  void add_quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, std::uint32_t mat = 0);
  void append(const TriangleMesh& other);
};

// Orientation and position: the mesh is scaled, turned about +x (rotation
// about the boresight, the radar's line of sight at boresight), tilted
// (about +y, nose up positive) and turned in azimuth (about +z), then moved.
// (Not `Placement`: ris/scene/scene_object.h has a ris::Placement of its own,
// and two classes of one name with default member initialisers give two
// inline constructors of one mangled name: the linker keeps either.)
struct MeshPlacement {
  double scale = 1.0;
  double roll_rad = 0.0;     // about +x (line of sight at boresight)
  double tilt_rad = 0.0;     // about -y: boresight raised by tilt
  double azimuth_rad = 0.0;  // about +z
  Vec3 position_m{};
};
void place(TriangleMesh& mesh, const MeshPlacement& p);

// Square plate of side a in the x = 0 plane, normal +x.
TriangleMesh make_plate(double side_m);
// Rectangular plate: width along y, height along z.
TriangleMesh make_plate(double width_m, double height_m);
// 90-degree dihedral: two plates of width b (from the fold) and height a
// (along the fold, z), fold along z through the origin, opening towards +x.
TriangleMesh make_dihedral(double height_m, double width_m);
// Trihedral corners of edge a on the three coordinate planes, the symmetry
// axis (1,1,1)/sqrt(3) turned onto +x: square plates, or triangular ones.
TriangleMesh make_trihedral_square(double edge_m);
TriangleMesh make_trihedral_triangular(double edge_m);
// Sphere of radius r centred at the origin: an icosahedron subdivided
// `subdivisions` times (20 * 4^n triangles), vertices on the sphere.
TriangleMesh make_sphere(double radius_m, int subdivisions);
// Closed cylinder of radius r, length L along z, centred at the origin,
// `segments` flat facets around.
TriangleMesh make_cylinder(double radius_m, double length_m, int segments);

}  // namespace ris
