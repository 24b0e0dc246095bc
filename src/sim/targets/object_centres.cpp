#include "ris/sim/object_centres.h"

#include <fmt/format.h>

#include <array>
#include <chrono>
#include <cmath>
#include <complex>
#include <exception>
#include <map>
#include <utility>

#include "ris/objects/material.h"
#include "ris/objects/object_scene.h"
#include "ris/objects/sbr.h"
#include "ris/sensor/track.h"
#include "ris/util/error.h"
#include "ris/util/units.h"

namespace ris {
namespace {

// Index into Sinclair (receive, transmit: HH, HV, VH, VV) of a radar's
// polarisation, which ris writes transmit first (docs/radar-format.md).
int sinclair_index(Polarisation p) {
  switch (p) {
    case Polarisation::HH:
      return 0;
    case Polarisation::VH:  // transmit V, receive H
      return 1;
    case Polarisation::HV:  // transmit H, receive V
      return 2;
    case Polarisation::VV:
      return 3;
  }
  return 0;
}

struct Cell {
  std::complex<double> s{};
  std::array<std::complex<double>, 4> s4{};  // a quad-pol run's S (SBR's index)
  double w = 0.0, w_along = 0.0, w_range = 0.0, w_height = 0.0;
  double n = 0.0, n_along = 0.0, n_range = 0.0, n_height = 0.0;
};

struct ObjectView {
  Vec3 to_radar;  // unit, local frame = world directions
  double reference_range_m = 0.0;
  Vec3 reference_local{};
};

// One object's centres (in cell order) and counts.
struct ObjectResult {
  std::vector<PointTarget> centres;
  std::int64_t rays_launched = 0, rays_traced = 0, returns = 0;
  double rcs_m2 = 0.0;
  bool behind_track = false;
};

struct TraceContext {
  const std::vector<CulturalObject>& objects;
  const Scene& scene;
  const Track& track;
  const ObjectSceneMesh& m;
  const EmbreeScene& bvh;
  double H, lambda, cell_m, frequency_hz;
  int pq;
};

ObjectResult trace_object(const TraceContext& ctx, std::size_t k) {
  const CulturalObject& obj = ctx.objects[k];
  const Scene& scene = ctx.scene;
  const Track& track = ctx.track;
  const ObjectSceneMesh& m = ctx.m;
  const double H = ctx.H, lambda = ctx.lambda, cell_m = ctx.cell_m;
  const int pq = ctx.pq;
  ObjectResult res;
  const Vec3 ref = m.centres_m[k] + m.origin_m;  // world
  const auto [s_ref, u_ref] = track.along_cross(ref.x, ref.y);
  if (!(u_ref > 0.0)) {
    res.behind_track = true;
    return res;
  }
  const auto [rx, ry] = track.world_from_along_cross(s_ref, 0.0);
  const Vec3 radar_pos{rx, ry, H};
  const Vec3 d = radar_pos - ref;
  ObjectView v{d.normalized(), d.norm(), m.centres_m[k]};

  SbrOptions o;
  o.max_bounces = 3;
  o.keep_returns = true;
  o.skip_ground_only = true;
  o.only_part = static_cast<std::uint32_t>(k + 1);
  // The launch window: the object, and for a building the ground in front
  // of it from which a ground-wall path can reach the wall, h tan(theta)
  // towards the radar (a cell more).
  std::vector<Vec3> window = m.windows[k];
  if (obj.kind == CulturalKind::building) {
    const double reach =
        obj.height_m * std::sqrt(1.0 - v.to_radar.z * v.to_radar.z) / v.to_radar.z + cell_m;
    const Vec3 towards = Vec3{v.to_radar.x, v.to_radar.y, 0.0}.normalized() * reach;
    for (const auto& p : obj.footprint_m) {
      window.push_back(Vec3{p[0], p[1], obj.base_m} - m.origin_m + towards);
    }
  }
  o.launch_extent = &window;
  // Tubes: a quarter cell on buildings, a 32nd of a reflector's size;
  // never finer than lambda / 10 (docs/objects.md "Objects in a scene").
  o.ray_spacing_m = std::max(lambda / 10.0, obj.kind == CulturalKind::building
                                                ? cell_m / 4.0
                                                : std::max(obj.size_m, obj.width_m) / 32.0);
  const SbrResult r = trace_sbr(ctx.bvh, m.surfaces, ctx.frequency_hz, v.to_radar, o);
  res.rays_launched = r.rays_launched;
  res.rays_traced = r.rays_traced;
  res.returns = static_cast<std::int64_t>(r.returns.size());

  const bool one_centre = obj.kind == CulturalKind::reflector;
  std::map<std::pair<std::int64_t, std::int64_t>, Cell> cells;
  std::complex<double> total{};
  for (const SbrReturn& ret : r.returns) {
    // Slant range: the plane wave's range to the reference point, moved
    // by the return's two-way path about the local origin's plane.
    const double range_m =
        v.reference_range_m + 0.5 * ret.path_m + v.to_radar.dot(v.reference_local);
    const Vec3 mid = (ret.first_hit_m + ret.last_hit_m) * 0.5 + m.origin_m;
    const double along_m = track.along_cross(mid.x, mid.y).first;
    const double h_m = std::min(ret.first_hit_m.z, ret.last_hit_m.z) + m.origin_m.z;
    // The cell's weight: |S_pq|^2 of the run's polarisation, or a quad-pol
    // run's span / 2 (what a trihedral's co-pol RCS is), which places one
    // centre for all four channels.
    const std::complex<double> s = pq >= 0 ? ret.s[static_cast<std::size_t>(pq)] : 0.0;
    total += s;
    const auto key = one_centre ? std::pair<std::int64_t, std::int64_t>{0, 0}
                                : std::pair<std::int64_t, std::int64_t>{
                                      static_cast<std::int64_t>(std::floor(along_m / cell_m)),
                                      static_cast<std::int64_t>(std::floor(range_m / cell_m))};
    Cell& c = cells[key];
    double w = std::norm(s);
    if (pq < 0) {
      w = 0.0;
      for (std::size_t i = 0; i < 4; ++i) {
        c.s4[i] += ret.s[i];
        w += 0.5 * std::norm(ret.s[i]);
      }
    }
    c.s += s;
    c.w += w;
    c.w_along += w * along_m;
    c.w_range += w * range_m;
    c.w_height += w * h_m;
    c.n += 1.0;
    c.n_along += along_m;
    c.n_range += range_m;
    c.n_height += h_m;
  }
  res.rcs_m2 = std::norm(total);
  if (pq < 0) {
    std::array<std::complex<double>, 4> sum{};
    for (const auto& [key, c] : cells)
      for (std::size_t i = 0; i < 4; ++i) sum[i] += c.s4[i];
    res.rcs_m2 = 0.0;
    for (std::size_t i = 0; i < 4; ++i) res.rcs_m2 += 0.5 * std::norm(sum[i]);
  }
  int n = 0;
  for (const auto& [key, c] : cells) {
    double rcs = std::norm(c.s);
    if (pq < 0) {
      rcs = 0.0;
      for (std::size_t i = 0; i < 4; ++i) rcs += 0.5 * std::norm(c.s4[i]);
    }
    if (!(rcs > 0.0)) continue;
    const bool weighted = c.w > 0.0;
    const double along = weighted ? c.w_along / c.w : c.n_along / c.n;
    const double range = weighted ? c.w_range / c.w : c.n_range / c.n;
    const double h = weighted ? c.w_height / c.w : c.n_height / c.n;
    const double dz = H - h;
    if (!(range > dz && dz > 0.0)) continue;
    const double u = std::sqrt(range * range - dz * dz);
    const auto [x, y] = track.world_from_along_cross(along, u);
    const double terrain = terrain_height_at(scene, x, y);
    if (!std::isfinite(terrain)) continue;  // imaged off the scene
    PointTarget t;
    t.name = fmt::format("{} centre {}", obj.label, n++);
    t.x_m = x;
    t.y_m = y;
    t.height_m = h - terrain;
    t.rcs_m2 = rcs;
    if (pq < 0) t.sinclair = c.s4;
    t.source_file = obj.source;
    t.index = static_cast<int>(k);
    t.from_object = true;
    res.centres.push_back(std::move(t));
  }
  return res;
}

}  // namespace

std::vector<PointTarget> object_scattering_centres(const std::vector<CulturalObject>& objects,
                                                   const Scene& scene, const RadarParams& radar,
                                                   ObjectCentreStats* stats) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<PointTarget> out;
  if (objects.empty()) return out;
  if (radar.mode == RadarMode::ppi) {
    throw InputError(objects[0].source, objects[0].label,
                     "scene objects are traced for SLAR and SAR tracks only; a PPI's rays do not "
                     "take them yet (use a SLAR/SAR radar, or a scene without buildings and "
                     "reflectors)");
  }
  const Track track = resolve_track(radar.track, scene, radar.source_file);
  const double H = track.altitude_m;
  const MaterialLibrary library = MaterialLibrary::load(default_materials_path());
  const ObjectSceneMesh m = build_object_scene(objects, scene, library, radar.frequency_hz);
  const EmbreeScene bvh(m.mesh);
  const double lambda = kSpeedOfLight_m_per_s / radar.frequency_hz;
  // -1: every element of S (a quad-pol SAR, ris/sim/sar_quad_pol.h).
  const int pq =
      radar.mode == RadarMode::sar && radar.sar.quad_pol ? -1 : sinclair_index(radar.polarisation);
  const double cell_m = std::max(scene.dx_m, scene.dy_m);
  ObjectCentreStats st;
  st.objects = static_cast<std::int64_t>(objects.size());
  st.triangles = static_cast<std::int64_t>(m.mesh.triangles.size());
  st.rcs_m2.assign(objects.size(), 0.0);

  // Objects in parallel, each traced on one thread (trace_sbr's own region
  // is then a team of one); their centres joined in object order, so the
  // list does not depend on the thread count.
  const TraceContext ctx{objects, scene, track, m, bvh, H, lambda, cell_m, radar.frequency_hz, pq};
  std::vector<ObjectResult> per(objects.size());
  std::exception_ptr failed;
#pragma omp parallel for schedule(dynamic, 1)
  for (std::size_t k = 0; k < objects.size(); ++k) {
    try {
      per[k] = trace_object(ctx, k);
    } catch (...) {
#pragma omp critical(ris_object_centres)
      if (!failed) failed = std::current_exception();
    }
  }
  if (failed) std::rethrow_exception(failed);
  for (std::size_t k = 0; k < objects.size(); ++k) {
    ObjectResult& r = per[k];
    st.behind_track += r.behind_track ? 1 : 0;
    st.rays_launched += r.rays_launched;
    st.rays_traced += r.rays_traced;
    st.returns += r.returns;
    st.rcs_m2[k] = r.rcs_m2;
    out.insert(out.end(), std::make_move_iterator(r.centres.begin()),
               std::make_move_iterator(r.centres.end()));
  }
  st.centres = static_cast<std::int64_t>(out.size());
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (stats != nullptr) *stats = std::move(st);
  return out;
}

nlohmann::json object_centre_stats_json(const ObjectCentreStats& st) {
  nlohmann::json rcs = nlohmann::json::array();
  for (double r : st.rcs_m2) {
    rcs.push_back({{"rcs_m2", r}, {"rcs_dbsm", r > 0.0 ? 10.0 * std::log10(r) : -999.0}});
  }
  return {{"objects", st.objects},
          {"triangles", st.triangles},
          {"rays_launched", st.rays_launched},
          {"rays_traced", st.rays_traced},
          {"returns", st.returns},
          {"scattering_centres", st.centres},
          {"behind_track", st.behind_track},
          {"by_object", rcs},
          {"method", "SBR, 3 bounces; returns placed as RaySAR (docs/objects.md)"}};
}

}  // namespace ris
