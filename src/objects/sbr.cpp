#include "ris/objects/sbr.h"

#include <embree3/rtcore.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "ris/objects/fresnel.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {

struct EmbreeScene::Handles {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  ~Handles() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }
};

EmbreeScene::EmbreeScene(const TriangleMesh& mesh) : handles_(new Handles), mesh_(mesh) {
  handles_->device = rtcNewDevice(nullptr);
  if (!handles_->device) throw std::runtime_error("Embree: rtcNewDevice failed");
  handles_->scene = rtcNewScene(handles_->device);
  RTCGeometry geom = rtcNewGeometry(handles_->device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(
      geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    v[3 * i] = static_cast<float>(mesh.vertices[i].x);
    v[3 * i + 1] = static_cast<float>(mesh.vertices[i].y);
    v[3 * i + 2] = static_cast<float>(mesh.vertices[i].z);
  }
  auto* idx = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0,
                                                             RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
                                                             mesh.triangles.size()));
  normals_.reserve(mesh.triangles.size());
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    idx[3 * i] = t[0];
    idx[3 * i + 1] = t[1];
    idx[3 * i + 2] = t[2];
    const Vec3 e1 = mesh.vertices[t[1]] - mesh.vertices[t[0]];
    const Vec3 e2 = mesh.vertices[t[2]] - mesh.vertices[t[0]];
    normals_.push_back(e1.cross(e2).normalized());
  }
  // A bounding sphere (the box's centre): where a window's rays start.
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (const Vec3& p : mesh.vertices) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  if (!mesh.vertices.empty()) {
    bound_centre_ = (lo + hi) * 0.5;
    bound_radius_ = (hi - lo).norm() * 0.5;
  }
  rtcCommitGeometry(geom);
  rtcAttachGeometry(handles_->scene, geom);
  rtcReleaseGeometry(geom);
  rtcCommitScene(handles_->scene);
}

EmbreeScene::~EmbreeScene() = default;

void* EmbreeScene::handle() const {
  return handles_->scene;
}

Vec3 radar_direction(double azimuth_rad, double elevation_rad) {
  return {std::cos(elevation_rad) * std::cos(azimuth_rad),
          std::cos(elevation_rad) * std::sin(azimuth_rad), std::sin(elevation_rad)};
}

namespace {

using cd = std::complex<double>;

struct CVec3 {
  cd x, y, z;
  CVec3 operator+(const CVec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  CVec3 operator-(const CVec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  CVec3 operator*(cd s) const { return {x * s, y * s, z * s}; }
};
CVec3 cvec(const Vec3& v, cd s) {
  return {v.x * s, v.y * s, v.z * s};
}
cd dot(const CVec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
CVec3 cross(const Vec3& a, const CVec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
CVec3 cross(const CVec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double sinc(double x) {
  return std::abs(x) < 1e-8 ? 1.0 : std::sin(x) / x;
}

struct Frame {
  Vec3 s, k, h, v;  // to radar, incident propagation, H and V (backscatter alignment)
};

Frame radar_frame(const Vec3& to_radar) {
  Frame f;
  f.s = to_radar.normalized();
  f.k = -f.s;
  Vec3 h = Vec3{0, 0, 1}.cross(f.k);
  if (h.norm() < 1e-9) h = {0, 1, 0};
  f.h = h.normalized();
  f.v = f.k.cross(f.h);  // (h, v, k) right-handed: at elevation 0, v is +z
  return f;
}

struct Accumulator {
  Sinclair s{};
  std::array<Sinclair, 8> by_bounce{};
  std::vector<SbrReturn> returns;
  std::int64_t traced = 0;
};

struct TraceContext {
  RTCScene scene;
  const EmbreeScene* es;
  const std::vector<SurfaceResponse>* surfaces;
  Frame f;
  double k;
  double offset;
  const SbrOptions* opt;
};

bool sees_radar(const TraceContext& c, const Vec3& p, std::int64_t& traced) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  RTCRay ray{};
  ray.org_x = static_cast<float>(p.x);
  ray.org_y = static_cast<float>(p.y);
  ray.org_z = static_cast<float>(p.z);
  ray.dir_x = static_cast<float>(c.f.s.x);
  ray.dir_y = static_cast<float>(c.f.s.y);
  ray.dir_z = static_cast<float>(c.f.s.z);
  ray.tnear = 0.0f;
  ray.tfar = std::numeric_limits<float>::infinity();
  ray.mask = 0xFFFFFFFFu;
  rtcOccluded1(c.scene, &ctx, &ray);
  ++traced;
  return ray.tfar >= 0.0f;  // Embree sets tfar to -inf when occluded
}

// One ray of the grid from p0 along f.k, tube edges a1, a2.
void trace_ray(const TraceContext& c, const Vec3& p0, Vec3 a1, Vec3 a2, std::int64_t ray_index,
               Accumulator& acc) {
  RTCIntersectContext ctx;
  rtcInitIntersectContext(&ctx);
  const Frame& f = c.f;
  CVec3 e[2] = {cvec(f.h, 1.0), cvec(f.v, 1.0)};  // H and V transmissions
  Vec3 org = p0, dir = f.k, first{};
  double path = 0.0;
  const std::vector<std::uint32_t>& parts = c.es->mesh().part;
  std::uint32_t part = 0;
  const double eta_free = 1.0;  // fields normalised by eta: eta H = k x E
  for (int bounce = 1; bounce <= c.opt->max_bounces; ++bounce) {
    RTCRayHit rh{};
    rh.ray.org_x = static_cast<float>(org.x);
    rh.ray.org_y = static_cast<float>(org.y);
    rh.ray.org_z = static_cast<float>(org.z);
    rh.ray.dir_x = static_cast<float>(dir.x);
    rh.ray.dir_y = static_cast<float>(dir.y);
    rh.ray.dir_z = static_cast<float>(dir.z);
    rh.ray.tnear = 0.0f;
    rh.ray.tfar = std::numeric_limits<float>::infinity();
    rh.ray.mask = 0xFFFFFFFFu;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(c.scene, &ctx, &rh);
    ++acc.traced;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) break;
    const double t = rh.ray.tfar;
    const Vec3 hit = org + dir * t;
    if (bounce == 1) first = hit;
    path += t;
    const std::uint32_t prim = rh.hit.primID;
    if (part == 0 && !parts.empty()) part = parts[prim];
    const bool counted = !(c.opt->skip_ground_only && part == 0) &&
                         !(c.opt->only_part != 0 && part != c.opt->only_part);
    Vec3 n = c.es->normals()[prim];
    if (n.dot(dir) > 0.0) n = -n;
    const double cos_i = -dir.dot(n);
    const SurfaceResponse& surf = (*c.surfaces)[c.es->mesh().material[prim]];
    FresnelPair r = surf.pec ? pec_reflection() : fresnel_reflection(surf.eps, cos_i);
    if (surf.rms_height_m > 0.0) {
      const double g = ament_amplitude_factor(c.k, surf.rms_height_m, cos_i);
      r.s *= g;
      r.p *= g;
    }
    Vec3 es = dir.cross(n);
    if (es.norm() < 1e-9) es = a1 - dir * a1.dot(dir);
    es = es.normalized();
    const Vec3 ep_i = es.cross(dir);
    const Vec3 kr = dir + n * (2.0 * cos_i);
    const Vec3 ep_r = es.cross(kr);
    CVec3 er[2];
    for (int i = 0; i < 2; ++i) {
      er[i] = cvec(es, r.s * dot(e[i], es)) + cvec(ep_r, r.p * dot(e[i], ep_i));
    }
    // Footprint of the tube on the facet (edges projected along dir).
    a1 = a1 - dir * (a1.dot(n) / dir.dot(n));
    a2 = a2 - dir * (a2.dot(n) / dir.dot(n));
    const double area = a1.cross(a2).norm();
    if (counted && f.s.dot(n) > 0.0 &&
        (bounce == 1 || sees_radar(c, hit + n * c.offset, acc.traced))) {
      const Vec3 w = f.s - dir;
      const double shape = sinc(0.5 * c.k * w.dot(a1)) * sinc(0.5 * c.k * w.dot(a2));
      const double two_way = -f.s.dot(p0) + path - f.s.dot(hit);
      // E_s = -j k / (4 pi) [eta N_perp + L x s] (Balanis 2012, 6.122), N = J A, L = M A.
      const cd amp = cd(0.0, -c.k / (4.0 * kPi)) * area * shape * std::sqrt(4.0 * kPi) *
                     std::exp(cd(0.0, -c.k * two_way));
      SbrReturn ret;
      for (int i = 0; i < 2; ++i) {
        const CVec3 eta_j = cross(n, cross(dir, e[i]) + cross(kr, er[i])) * eta_free;
        const CVec3 m = cross(e[i] + er[i], n);
        const CVec3 eta_j_perp = eta_j - cvec(f.s, dot(eta_j, f.s));
        const CVec3 es_vec = (eta_j_perp + cross(m, f.s)) * amp;
        ret.s[i] = dot(es_vec, f.h);      // i = 0: HH, i = 1: HV
        ret.s[2 + i] = dot(es_vec, f.v);  // VH, VV
      }
      for (int q = 0; q < 4; ++q) {
        acc.s[q] += ret.s[q];
        acc.by_bounce[std::min(bounce, 7)][q] += ret.s[q];
      }
      if (c.opt->keep_returns) {
        ret.path_m = two_way;
        ret.bounces = bounce;
        ret.first_hit_m = first;
        ret.last_hit_m = hit;
        ret.part = part;
        ret.ray = ray_index;
        acc.returns.push_back(ret);
      }
    }
    e[0] = er[0];
    e[1] = er[1];
    org = hit + n * c.offset;
    dir = kr.normalized();
  }
}

}  // namespace

SbrResult trace_sbr(const EmbreeScene& scene, const std::vector<SurfaceResponse>& surfaces,
                    double frequency_hz, const Vec3& to_radar, const SbrOptions& options) {
  RIS_CHECK(frequency_hz > 0.0 && options.rays_per_wavelength > 0.0 && options.max_bounces >= 1);
  for (std::uint32_t m : scene.mesh().material) RIS_CHECK(m < surfaces.size());
  const auto start = std::chrono::steady_clock::now();
  const double lambda = kSpeedOfLight_m_per_s / frequency_hz;
  TraceContext c{static_cast<RTCScene>(scene.handle()),
                 &scene,
                 &surfaces,
                 radar_frame(to_radar),
                 2.0 * kPi / lambda,
                 0.0,
                 &options};
  // The grid covers the mesh's projection on the (h, v) plane.
  double umin = 1e300, umax = -1e300, vmin = 1e300, vmax = -1e300, smax = -1e300, extent = 0.0;
  if (options.launch_extent != nullptr) {
    // A window of a large mesh: start beyond its bounding sphere (a pass
    // over every vertex per window would cost more than the window's rays).
    smax = c.f.s.dot(scene.bound_centre()) + scene.bound_radius();
    extent = scene.bound_centre().norm() + scene.bound_radius();
  } else {
    for (const Vec3& p : scene.mesh().vertices) {
      smax = std::max(smax, p.dot(c.f.s));
      extent = std::max(extent, p.norm());
    }
  }
  const std::vector<Vec3>& window =
      options.launch_extent != nullptr ? *options.launch_extent : scene.mesh().vertices;
  for (const Vec3& p : window) {
    umin = std::min(umin, p.dot(c.f.h));
    umax = std::max(umax, p.dot(c.f.h));
    vmin = std::min(vmin, p.dot(c.f.v));
    vmax = std::max(vmax, p.dot(c.f.v));
  }
  SbrResult result;
  if (scene.mesh().vertices.empty() || window.empty()) return result;
  c.offset = 1e-5 * std::max(extent, lambda);
  const double d =
      options.ray_spacing_m > 0.0 ? options.ray_spacing_m : lambda / options.rays_per_wavelength;
  const auto nu = static_cast<std::int64_t>(std::ceil((umax - umin) / d)) + 1;
  const auto nv = static_cast<std::int64_t>(std::ceil((vmax - vmin) / d)) + 1;
  const double u0 = 0.5 * (umin + umax) - 0.5 * static_cast<double>(nu - 1) * d;
  const double v0 = 0.5 * (vmin + vmax) - 0.5 * static_cast<double>(nv - 1) * d;
  const Vec3 base = c.f.s * (smax + lambda);
  std::vector<Accumulator> accs(static_cast<std::size_t>(omp_get_max_threads()));
#pragma omp parallel for schedule(dynamic, 4)
  for (std::int64_t iu = 0; iu < nu; ++iu) {
    Accumulator& acc = accs[static_cast<std::size_t>(omp_get_thread_num())];
    for (std::int64_t iv = 0; iv < nv; ++iv) {
      const Vec3 p0 = base + c.f.h * (u0 + static_cast<double>(iu) * d) +
                      c.f.v * (v0 + static_cast<double>(iv) * d);
      trace_ray(c, p0, c.f.h * d, c.f.v * d, iu * nv + iv, acc);
    }
  }
  for (Accumulator& a : accs) {
    for (int q = 0; q < 4; ++q) result.s[q] += a.s[q];
    for (std::size_t b = 0; b < 8; ++b) {
      for (int q = 0; q < 4; ++q) result.by_bounce[b][q] += a.by_bounce[b][q];
    }
    result.rays_traced += a.traced;
    result.returns.insert(result.returns.end(), a.returns.begin(), a.returns.end());
  }
  // The threads' lists in launch order, whatever the thread count.
  std::sort(result.returns.begin(), result.returns.end(),
            [](const SbrReturn& a, const SbrReturn& b) {
              return a.ray != b.ray ? a.ray < b.ray : a.bounces < b.bounces;
            });
  for (int q = 0; q < 4; ++q) result.rcs_m2[q] = std::norm(result.s[q]);
  result.rays_launched = nu * nv;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace ris
