#include "ris/objects/mesh.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "ris/util/units.h"

namespace ris {
namespace {

Vec3 rotate_x(const Vec3& v, double a) {
  return {v.x, std::cos(a) * v.y - std::sin(a) * v.z, std::sin(a) * v.y + std::cos(a) * v.z};
}
Vec3 rotate_y(const Vec3& v, double a) {
  return {std::cos(a) * v.x + std::sin(a) * v.z, v.y, -std::sin(a) * v.x + std::cos(a) * v.z};
}
Vec3 rotate_z(const Vec3& v, double a) {
  return {std::cos(a) * v.x - std::sin(a) * v.y, std::sin(a) * v.x + std::cos(a) * v.y, v.z};
}

// Rodrigues: the rotation taking unit u onto +x, applied to every vertex.
void turn_onto_x(TriangleMesh& m, const Vec3& u) {
  const Vec3 x{1.0, 0.0, 0.0};
  const Vec3 axis = u.cross(x);
  const double s = axis.norm();
  const double c = u.dot(x);
  if (s < 1e-15) return;
  const Vec3 k = axis * (1.0 / s);
  for (Vec3& v : m.vertices) {
    v = v * c + k.cross(v) * s + k * (k.dot(v) * (1.0 - c));
  }
}

}  // namespace

void TriangleMesh::add_triangle(const Vec3& a, const Vec3& b, const Vec3& c, std::uint32_t mat) {
  const auto n = static_cast<std::uint32_t>(vertices.size());
  vertices.push_back(a);
  vertices.push_back(b);
  vertices.push_back(c);
  triangles.push_back({n, n + 1, n + 2});
  material.push_back(mat);
}

void TriangleMesh::add_quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d,
                            std::uint32_t mat) {
  add_triangle(a, b, c, mat);
  add_triangle(a, c, d, mat);
}

void TriangleMesh::append(const TriangleMesh& other) {
  const auto n = static_cast<std::uint32_t>(vertices.size());
  vertices.insert(vertices.end(), other.vertices.begin(), other.vertices.end());
  for (const auto& t : other.triangles) triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  material.insert(material.end(), other.material.begin(), other.material.end());
  if (!part.empty() || !other.part.empty()) {
    part.resize(triangles.size() - other.triangles.size(), 0);
    if (other.part.empty()) {
      part.resize(triangles.size(), 0);
    } else {
      part.insert(part.end(), other.part.begin(), other.part.end());
    }
  }
}

void place(TriangleMesh& mesh, const MeshPlacement& p) {
  for (Vec3& v : mesh.vertices) {
    Vec3 w = rotate_x(v * p.scale, p.roll_rad);
    w = rotate_y(w, -p.tilt_rad);
    w = rotate_z(w, p.azimuth_rad);
    v = w + p.position_m;
  }
}

TriangleMesh make_plate(double width_m, double height_m) {
  TriangleMesh m;
  const double w = 0.5 * width_m, h = 0.5 * height_m;
  m.add_quad({0, -w, -h}, {0, w, -h}, {0, w, h}, {0, -w, h});
  return m;
}

TriangleMesh make_plate(double side_m) {
  return make_plate(side_m, side_m);
}

TriangleMesh make_dihedral(double height_m, double width_m) {
  TriangleMesh m;
  const double h = 0.5 * height_m, b = width_m;
  m.add_quad({0, 0, -h}, {b, 0, -h}, {b, 0, h}, {0, 0, h});  // y = 0 plane
  m.add_quad({0, 0, -h}, {0, b, -h}, {0, b, h}, {0, 0, h});  // x = 0 plane
  // Opening (1,1,0)/sqrt(2) onto +x.
  for (Vec3& v : m.vertices) v = rotate_z(v, -kPi / 4.0);
  return m;
}

TriangleMesh make_trihedral_square(double edge_m) {
  TriangleMesh m;
  const double a = edge_m;
  m.add_quad({0, 0, 0}, {a, 0, 0}, {a, a, 0}, {0, a, 0});
  m.add_quad({0, 0, 0}, {0, a, 0}, {0, a, a}, {0, 0, a});
  m.add_quad({0, 0, 0}, {0, 0, a}, {a, 0, a}, {a, 0, 0});
  turn_onto_x(m, Vec3{1, 1, 1}.normalized());
  return m;
}

TriangleMesh make_trihedral_triangular(double edge_m) {
  TriangleMesh m;
  const double a = edge_m;
  m.add_triangle({0, 0, 0}, {a, 0, 0}, {0, a, 0});
  m.add_triangle({0, 0, 0}, {0, a, 0}, {0, 0, a});
  m.add_triangle({0, 0, 0}, {0, 0, a}, {a, 0, 0});
  turn_onto_x(m, Vec3{1, 1, 1}.normalized());
  return m;
}

TriangleMesh make_sphere(double radius_m, int subdivisions) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> v = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                         {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& p : v) p = p.normalized();
  std::vector<std::array<std::uint32_t, 3>> f = {
      {0, 11, 5},  {0, 5, 1},  {0, 1, 7},  {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
      {11, 10, 2}, {10, 7, 6}, {7, 1, 8},  {3, 9, 4},  {3, 4, 2},   {3, 2, 6}, {3, 6, 8},
      {3, 8, 9},   {4, 9, 5},  {2, 4, 11}, {6, 2, 10}, {8, 6, 7},   {9, 8, 1}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> mid;
    auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(((v[a] + v[b]) * 0.5).normalized());
      const auto i = static_cast<std::uint32_t>(v.size() - 1);
      mid.emplace(key, i);
      return i;
    };
    std::vector<std::array<std::uint32_t, 3>> g;
    g.reserve(f.size() * 4);
    for (const auto& tri : f) {
      const std::uint32_t ab = midpoint(tri[0], tri[1]), bc = midpoint(tri[1], tri[2]),
                          ca = midpoint(tri[2], tri[0]);
      g.push_back({tri[0], ab, ca});
      g.push_back({tri[1], bc, ab});
      g.push_back({tri[2], ca, bc});
      g.push_back({ab, bc, ca});
    }
    f = std::move(g);
  }
  TriangleMesh m;
  for (Vec3& p : v) m.vertices.push_back(p * radius_m);
  m.triangles = std::move(f);
  m.material.assign(m.triangles.size(), 0);
  return m;
}

TriangleMesh make_cylinder(double radius_m, double length_m, int segments) {
  TriangleMesh m;
  const double h = 0.5 * length_m;
  // Facet centres on the angles 2 pi i / n: one facet faces +x (broadside).
  for (int i = 0; i < segments; ++i) {
    const double a0 = 2.0 * kPi * (i - 0.5) / segments, a1 = 2.0 * kPi * (i + 0.5) / segments;
    const Vec3 p0{radius_m * std::cos(a0), radius_m * std::sin(a0), 0.0};
    const Vec3 p1{radius_m * std::cos(a1), radius_m * std::sin(a1), 0.0};
    const Vec3 up{0, 0, h};
    m.add_quad(p0 - up, p1 - up, p1 + up, p0 + up);
    m.add_triangle({0, 0, h}, p0 + up, p1 + up);
    m.add_triangle({0, 0, -h}, p1 - up, p0 - up);
  }
  return m;
}

}  // namespace ris
