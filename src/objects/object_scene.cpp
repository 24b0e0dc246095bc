#include "ris/objects/object_scene.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "ris/geometry/terrain_sample.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

using Point = std::array<double, 2>;

double cross2(const Point& o, const Point& a, const Point& b) {
  return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
}

bool in_triangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  return cross2(a, b, p) >= 0.0 && cross2(b, c, p) >= 0.0 && cross2(c, a, p) >= 0.0;
}

// The materials of the mesh, each name once, in first-use order.
class SurfaceTable {
 public:
  SurfaceTable(const MaterialLibrary& lib, double frequency_hz) : lib_(lib), f_(frequency_hz) {}
  std::uint32_t index(const std::string& name, const CulturalObject& o, const std::string& key) {
    if (auto it = index_.find(name); it != index_.end()) return it->second;
    const Material* m = nullptr;
    try {
      m = &lib_.find(name);
    } catch (const InputError& e) {
      throw InputError(o.source, o.label + "." + key, e.what());
    }
    SurfaceResponse s;
    s.pec = m->is_pec();
    if (!s.pec) s.eps = m->permittivity(f_);
    s.rms_height_m = m->rms_height_m;
    const auto i = static_cast<std::uint32_t>(surfaces.size());
    surfaces.push_back(s);
    names.push_back(name);
    index_[name] = i;
    return i;
  }
  std::vector<SurfaceResponse> surfaces;
  std::vector<std::string> names;

 private:
  const MaterialLibrary& lib_;
  double f_;
  std::map<std::string, std::uint32_t> index_;
};

void add_part(TriangleMesh& mesh, TriangleMesh piece, std::uint32_t part) {
  piece.part.assign(piece.triangles.size(), part);
  mesh.append(piece);
}

TriangleMesh building_mesh(const CulturalObject& b, const Vec3& origin, std::uint32_t wall,
                           std::uint32_t roof) {
  TriangleMesh m;
  const std::size_t n = b.footprint_m.size();
  const double z0 = b.base_m - origin.z, z1 = b.base_m + b.height_m - origin.z;
  const auto at = [&](std::size_t i, double z) {
    return Vec3{b.footprint_m[i][0] - origin.x, b.footprint_m[i][1] - origin.y, z};
  };
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    m.add_quad(at(i, z0), at(j, z0), at(j, z1), at(i, z1), wall);
  }
  for (const auto& t : triangulate_polygon(b.footprint_m)) {
    m.add_triangle(at(t[0], z1), at(t[1], z1), at(t[2], z1), roof);
  }
  return m;
}

TriangleMesh reflector_shape_mesh(const CulturalObject& r, double lambda_m) {
  // Facets well inside the first Fresnel zone sqrt(lambda r) (docs/objects.md).
  const double fresnel = std::sqrt(lambda_m * r.size_m);
  switch (r.shape) {
    case ReflectorShape::plate:
      return make_plate(r.width_m, r.size_m);
    case ReflectorShape::dihedral:
      return make_dihedral(r.size_m, r.width_m);
    case ReflectorShape::trihedral:
      return make_trihedral_square(r.size_m);
    case ReflectorShape::triangular_trihedral:
      return make_trihedral_triangular(r.size_m);
    case ReflectorShape::sphere: {
      int n = 0;
      while (n < 7 && 1.1 * r.size_m / std::pow(2.0, n) > fresnel / 8.0) ++n;
      return make_sphere(r.size_m, n);
    }
    case ReflectorShape::cylinder:
      return make_cylinder(
          r.size_m, r.width_m,
          std::max(64, static_cast<int>(std::ceil(2.0 * kPi * r.size_m / (fresnel / 20.0)))));
  }
  RIS_CHECK(false);
  return {};
}

// Marks the grid cells of every building's apron; ground heights of cells
// under a footprint set to the building's base.
struct Apron {
  std::vector<std::uint8_t> in;
  std::vector<float> height_m;
};

Apron ground_apron(const std::vector<CulturalObject>& objects, const Scene& scene,
                   double apron_factor) {
  Apron a;
  a.in.assign(scene.size(), 0);
  a.height_m.assign(scene.elevation_m.begin(), scene.elevation_m.end());
  const double cell = std::max(scene.dx_m, scene.dy_m);
  for (const CulturalObject& b : objects) {
    if (b.kind != CulturalKind::building) continue;
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    for (const Point& p : b.footprint_m) {
      x0 = std::min(x0, p[0]);
      y0 = std::min(y0, p[1]);
      x1 = std::max(x1, p[0]);
      y1 = std::max(y1, p[1]);
    }
    const double pad = std::max(apron_factor * b.height_m, 2.0 * cell);
    const auto [c0, r1] = scene.grid_from_world(x0 - pad, y0 - pad);
    const auto [c1, r0] = scene.grid_from_world(x1 + pad, y1 + pad);
    const int rb = std::max(0, static_cast<int>(std::floor(r0))),
              re = std::min(scene.rows - 1, static_cast<int>(std::ceil(r1)));
    const int cb = std::max(0, static_cast<int>(std::floor(c0))),
              ce = std::min(scene.cols - 1, static_cast<int>(std::ceil(c1)));
    for (int r = rb; r <= re; ++r) {
      for (int c = cb; c <= ce; ++c) {
        const std::size_t i = scene.index(r, c);
        a.in[i] = 1;
        const auto [x, y] = scene.cell_centre(r, c);
        if (point_in_footprint(b.footprint_m, x, y)) a.height_m[i] = static_cast<float>(b.base_m);
      }
    }
  }
  return a;
}

std::int64_t add_ground(TriangleMesh& mesh, const Scene& scene, const Apron& a, const Vec3& origin,
                        std::uint32_t material) {
  std::int64_t added = 0;
  std::vector<std::uint32_t> vertex(scene.size(), UINT32_MAX);
  const auto v = [&](int r, int c) {
    const std::size_t i = scene.index(r, c);
    if (vertex[i] == UINT32_MAX) {
      const auto [x, y] = scene.cell_centre(r, c);
      vertex[i] = static_cast<std::uint32_t>(mesh.vertices.size());
      mesh.vertices.push_back({x - origin.x, y - origin.y, double(a.height_m[i]) - origin.z});
    }
    return vertex[i];
  };
  for (int r = 0; r + 1 < scene.rows; ++r) {
    for (int c = 0; c + 1 < scene.cols; ++c) {
      const std::size_t i00 = scene.index(r, c), i01 = i00 + 1, i10 = scene.index(r + 1, c),
                        i11 = i10 + 1;
      if (!(a.in[i00] && a.in[i01] && a.in[i10] && a.in[i11])) continue;
      if (!(scene.valid[i00] && scene.valid[i01] && scene.valid[i10] && scene.valid[i11])) continue;
      const std::uint32_t q00 = v(r, c), q01 = v(r, c + 1), q10 = v(r + 1, c),
                          q11 = v(r + 1, c + 1);
      mesh.triangles.push_back({q00, q10, q11});
      mesh.triangles.push_back({q00, q11, q01});
      mesh.material.insert(mesh.material.end(), 2, material);
      mesh.part.insert(mesh.part.end(), 2, 0);
      added += 2;
    }
  }
  return added;
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(const std::vector<Point>& polygon) {
  std::vector<std::uint32_t> left(polygon.size());
  for (std::size_t i = 0; i < left.size(); ++i) left[i] = static_cast<std::uint32_t>(i);
  std::vector<std::array<std::uint32_t, 3>> out;
  while (left.size() > 3) {
    bool clipped = false;
    for (std::size_t k = 0; k < left.size(); ++k) {
      const std::uint32_t a = left[(k + left.size() - 1) % left.size()], b = left[k],
                          c = left[(k + 1) % left.size()];
      if (cross2(polygon[a], polygon[b], polygon[c]) <= 0.0) continue;  // reflex or flat
      bool empty = true;
      for (std::uint32_t p : left) {
        if (p != a && p != b && p != c &&
            in_triangle(polygon[p], polygon[a], polygon[b], polygon[c]))
          empty = false;
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      left.erase(left.begin() + static_cast<std::ptrdiff_t>(k));
      clipped = true;
      break;
    }
    // A simple counter-clockwise polygon always has an ear (Meisters 1975);
    // only collinear leftovers get here: fan them.
    if (!clipped) {
      for (std::size_t k = 1; k + 1 < left.size(); ++k)
        out.push_back({left[0], left[k], left[k + 1]});
      return out;
    }
  }
  out.push_back({left[0], left[1], left[2]});
  return out;
}

ObjectSceneMesh build_object_scene(const std::vector<CulturalObject>& objects, const Scene& scene,
                                   const MaterialLibrary& library, double frequency_hz,
                                   double apron_factor) {
  ObjectSceneMesh out;
  const auto [cx, cy] = scene.world_from_grid(0.5 * scene.cols, 0.5 * scene.rows);
  out.origin_m = {cx, cy, 0.0};
  const Vec3 o = out.origin_m;
  const double lambda = kSpeedOfLight_m_per_s / frequency_hz;
  SurfaceTable table(library, frequency_hz);
  std::int64_t triangles = 0;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const CulturalObject& b = objects[k];
    const auto part = static_cast<std::uint32_t>(k + 1);
    TriangleMesh piece;
    std::vector<Vec3> window;
    Vec3 centre{};
    if (b.kind == CulturalKind::building) {
      piece = building_mesh(b, o, table.index(b.wall_material, b, "wall_material"),
                            table.index(b.roof_material, b, "roof_material"));
      for (const Point& p : b.footprint_m) {
        centre += Vec3{p[0] - o.x, p[1] - o.y, b.base_m - o.z} *
                  (1.0 / static_cast<double>(b.footprint_m.size()));
      }
      window = piece.vertices;
    } else {
      const TerrainSample ts = bilinear_terrain_sample(scene, nullptr, b.x_m, b.y_m);
      if (!ts.valid) {
        throw InputError(b.source, b.label + ".x",
                         fmt::format("the reflector at ({:.1f}, {:.1f}) m is off the scene or on "
                                     "a no-data cell",
                                     b.x_m, b.y_m));
      }
      piece = reflector_shape_mesh(b, lambda);
      const std::uint32_t m = table.index(b.material, b, "material");
      std::fill(piece.material.begin(), piece.material.end(), m);
      MeshPlacement p;
      p.roll_rad = b.roll_rad;
      p.tilt_rad = b.tilt_rad;
      p.azimuth_rad = b.azimuth_rad;
      p.position_m = {b.x_m - o.x, b.y_m - o.y, double(ts.height_m) + b.height_above_terrain_m};
      place(piece, p);
      centre = p.position_m;
      window = piece.vertices;
    }
    triangles += static_cast<std::int64_t>(piece.triangles.size());
    add_part(out.mesh, std::move(piece), part);
    out.windows.push_back(std::move(window));
    out.centres_m.push_back(centre);
  }
  bool buildings = false;
  std::string ground = "concrete";
  const CulturalObject* first_building = nullptr;
  for (const CulturalObject& b : objects) {
    if (b.kind == CulturalKind::building && !buildings) {
      buildings = true;
      ground = b.ground_material;
      first_building = &b;
    }
  }
  if (buildings) {
    const Apron a = ground_apron(objects, scene, apron_factor);
    std::int64_t cells = 0;
    for (std::uint8_t x : a.in) cells += x;
    if (triangles + 2 * cells > kMaxObjectSceneTriangles) {
      throw InputError(first_building->source, "object",
                       fmt::format("the objects and the ground around them would make {} "
                                   "triangles, more than the {} allowed; use fewer or smaller "
                                   "objects, or a coarser scene",
                                   triangles + 2 * cells, kMaxObjectSceneTriangles));
    }
    out.ground_triangles =
        add_ground(out.mesh, scene, a, o, table.index(ground, *first_building, "ground_material"));
  }
  out.surfaces = std::move(table.surfaces);
  out.surface_names = std::move(table.names);
  return out;
}

}  // namespace ris
