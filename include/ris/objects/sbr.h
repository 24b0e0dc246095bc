// Shooting and bouncing rays (SBR) over a triangle mesh in one Embree BVH:
// the monostatic scattering matrix of an object lit by a plane wave
// (Ling, Chou & Lee 1989, IEEE TAP 37(2) 194-205; Bhalla & Ling 1993).
//
// A grid of parallel rays, spaced lambda / rays_per_wavelength over the
// object's projected extent, is traced up to max_bounces specular bounces.
// Each ray carries the fields of an H and of a V transmission (two complex
// 3-vectors, i.e. the 2x2 Sinclair matrix in each facet's s/p basis) and
// the path length; at every hit the physical-optics currents of the ray tube
// (J = n x (H_i + H_r), M = (E_i + E_r) x n, Fresnel r_s, r_p of the hit
// material) are radiated back to the radar when the hit point sees it.
// Conventions (backscatter alignment, S sign, phase e^{+jwt}): docs/objects.md.
//
// Example:
//   ris::EmbreeScene scene(ris::make_plate(1.0));
//   ris::SbrResult r = ris::trace_sbr(scene, {ris::pec_surface()}, 10e9,
//                                     ris::radar_direction(0.0, 0.0), {});
//   double sigma_hh_m2 = r.rcs_m2[0];
#pragma once

#include <array>
#include <complex>
#include <cstdint>
#include <memory>
#include <vector>

#include "ris/objects/mesh.h"
#include "ris/util/vec3.h"

namespace ris {

// What a surface does to a ray: a perfect conductor, or a dielectric
// half-space of complex permittivity, with an rms roughness (Ament factor).
struct SurfaceResponse {
  bool pec = true;
  std::complex<double> eps{1.0, 0.0};
  double rms_height_m = 0.0;
};
inline SurfaceResponse pec_surface() {
  return {};
}

// One Embree device and scene holding the mesh's triangles (one BVH, built
// once); RAII, not copyable.
class EmbreeScene {
 public:
  explicit EmbreeScene(const TriangleMesh& mesh);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  const TriangleMesh& mesh() const { return mesh_; }
  // The Embree RTCScene, as void* (the Embree header stays in the .cpp).
  void* handle() const;
  // Unit facet normals (right-hand rule of the vertex order).
  const std::vector<Vec3>& normals() const { return normals_; }
  // A sphere holding every vertex.
  const Vec3& bound_centre() const { return bound_centre_; }
  double bound_radius() const { return bound_radius_; }

 private:
  struct Handles;
  std::unique_ptr<Handles> handles_;
  TriangleMesh mesh_;
  std::vector<Vec3> normals_;
  Vec3 bound_centre_{};
  double bound_radius_ = 0.0;
};

struct SbrOptions {
  int max_bounces = 3;
  // Rays per wavelength along each axis of the launch grid (PO-SBR codes use
  // >= 10: the tubes then stay small against the wavelength, so the
  // tube-integral's linear-phase approximation holds).
  double rays_per_wavelength = 10.0;
  bool keep_returns = false;  // every (ray, bounce) contribution in SbrResult::returns
  // > 0: the launch grid's spacing in metres instead of lambda /
  // rays_per_wavelength (a scene's objects, ris/objects/object_scene.h: the
  // tube integral is exact on a flat facet whatever the tube's size).
  double ray_spacing_m = 0.0;
  // Launch only over the projection of these points (default: the whole
  // mesh); the rays still start beyond the whole mesh, so everything in
  // front of the window occludes it.
  const std::vector<Vec3>* launch_extent = nullptr;
  // With the mesh's parts (TriangleMesh::part): a path's part is the first
  // non-zero part it hits. skip_ground_only drops contributions of paths
  // that have hit part 0 only so far; only_part > 0 keeps those of that
  // part alone (each path is then counted by one window).
  bool skip_ground_only = false;
  std::uint32_t only_part = 0;
};

// S in backscatter alignment: index 0 HH, 1 HV, 2 VH, 3 VV (receive, transmit);
// normalised so that sigma_pq = |S_pq|^2 (m^2).
using Sinclair = std::array<std::complex<double>, 4>;

struct SbrReturn {
  Sinclair s{};
  double path_m =
      0.0;  // two-way path from the plane through the origin normal to the line of sight
  int bounces = 0;
  Vec3 first_hit_m{}, last_hit_m{};
  std::uint32_t part = 0;  // the path's first non-zero part (SbrOptions)
  std::int64_t ray = 0;    // the launch grid's index of its ray (returns are in ray order)
};

struct SbrResult {
  Sinclair s{};                         // coherent sum
  std::array<double, 4> rcs_m2{};       // |S|^2: HH, HV, VH, VV
  std::array<Sinclair, 8> by_bounce{};  // coherent sums by bounce count (index = bounces, <= 7)
  std::vector<SbrReturn> returns;       // with keep_returns
  std::int64_t rays_launched = 0;
  std::int64_t rays_traced = 0;  // every ray segment (bounce and visibility rays)
  double seconds = 0.0;
};

// The unit vector from the object towards the radar: azimuth from +x towards
// +y, elevation above the x-y plane.
Vec3 radar_direction(double azimuth_rad, double elevation_rad);

SbrResult trace_sbr(const EmbreeScene& scene, const std::vector<SurfaceResponse>& surfaces,
                    double frequency_hz, const Vec3& to_radar, const SbrOptions& options);

}  // namespace ris
