#include "bench_objects.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "ris/objects/mesh.h"
#include "ris/objects/sbr.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/object_centres.h"
#include "ris/util/units.h"

namespace ris::app {
namespace {

// A cluster of reflectors, 4-5 m across: trihedrals, dihedrals, plates, a
// cylinder and a sphere, 3,000-odd triangles, so that rays bounce between
// objects as in a street.
TriangleMesh bench_mesh() {
  TriangleMesh all;
  for (int i = 0; i < 4; ++i) {
    TriangleMesh t = i % 2 == 0 ? make_trihedral_square(0.6) : make_dihedral(1.0, 0.6);
    place(t, {.azimuth_rad = 0.3 * i, .position_m = {0.0, -2.0 + 1.3 * i, 0.0}});
    all.append(t);
  }
  TriangleMesh c = make_cylinder(0.4, 2.0, 512);
  place(c, {.position_m = {-1.5, 0.0, 0.5}});
  all.append(c);
  TriangleMesh s = make_sphere(0.5, 3);
  place(s, {.position_m = {-1.0, 1.8, 0.0}});
  all.append(s);
  TriangleMesh wall = make_plate(5.0, 2.5);
  place(wall, {.position_m = {-2.5, 0.0, 0.5}});
  all.append(wall);
  return all;
}

}  // namespace

void run_objects_bench(int repeats) {
  const TriangleMesh mesh = bench_mesh();
  EmbreeScene scene(mesh);
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(2);
  SbrOptions o;
  o.max_bounces = 3;
  std::vector<double> rate;
  SbrResult r;
  for (int i = 0; i < std::max(1, repeats); ++i) {
    r = trace_sbr(scene, {pec_surface()}, 10e9, radar_direction(deg_to_rad(20.0), deg_to_rad(30.0)),
                  o);
    rate.push_back(static_cast<double>(r.rays_traced) / r.seconds);
  }
  omp_set_num_threads(threads_before);
  std::sort(rate.begin(), rate.end());
  const double median = rate[rate.size() / 2];
  fmt::print(
      "ris bench --objects: SBR on {} triangles, 10 GHz, 10 rays per wavelength, up to {} "
      "bounces, 2 threads, median of {}\n"
      "  {} rays launched, {} ray segments (every bounce and visibility ray), {:.3f} s: "
      "{:.2f} M rays/s\n",
      mesh.triangles.size(), o.max_bounces, rate.size(), r.rays_launched, r.rays_traced, r.seconds,
      median / 1e6);
  fmt::print("objects_rays_per_s_2threads={:.0f}\n", median);
}

void run_town_bench(const std::string& data_dir) {
  // The shipped town (data/scenes/town.toml, 244 objects on 1 km^2 of 1 m
  // cells) as ris simulate traces it: mesh, BVH, tracing and binning into
  // scattering centres (ris/sim/object_centres.h), on 2 threads.
  const auto t0 = std::chrono::steady_clock::now();
  const LoadedScene town = load_scene_source(data_dir + "/scenes/town.toml");
  const RadarParams radar = load_radar(data_dir + "/radars/sar-x-band-town.toml");
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(2);
  ObjectCentreStats st;
  object_scattering_centres(town.cultural_objects, town.scene, radar, &st);
  omp_set_num_threads(threads_before);
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fmt::print(
      "  town (data/scenes/town.toml): {} objects, {} triangles, {} rays launched, {} segments, "
      "{} returns -> {} scattering centres in {:.2f} s ({:.2f} s tracing and binning: {:.2f} M "
      "rays/s)\n",
      st.objects, st.triangles, st.rays_launched, st.rays_traced, st.returns, st.centres, s,
      st.seconds, static_cast<double>(st.rays_traced) / st.seconds / 1e6);
  fmt::print("objects_town_seconds={:.3f}\n", s);
}

}  // namespace ris::app
