#include "bench_quad_pol.h"
#include "bench_timing.h"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <memory>
#include <vector>

#include "ris/backscatter/library.h"
#include "ris/scene/scene_source.h"
#include "ris/sensor/radar_config.h"
#include "ris/sim/object_centres.h"
#include "ris/sim/sar_coherent.h"
#include "ris/sim/sar_quad_pol.h"

namespace ris::app {

void run_quad_pol_bench(const std::string& data_dir, int repeats) {
  // Both runs image the town's grid and its objects' scattering centres
  // (traced once, outside the timing): the single-pol coherent SAR (HH) as
  // simulate_slar + coherent_sar_intensity, the quad-pol one as its three
  // channels over one geometry + form_quad_pol.
  const LoadedScene town = load_scene_source(data_dir + "/scenes/town.toml");
  const RadarParams quad = load_radar(data_dir + "/radars/sar-x-band-town-quadpol.toml");
  const RadarParams single = quad_pol_channel(quad, Polarisation::HH);
  const std::unique_ptr<Sigma0Source> sigma0 = load_sigma0_source(default_sigma0_library_path());
  SlarOptions options;
  options.targets = object_scattering_centres(town.cultural_objects, town.scene, quad);
  const CategoryShapes shapes = scene_polarimetry(town.scene, *sigma0, quad);
  const int threads_before = omp_get_max_threads();
  omp_set_num_threads(2);
  std::vector<double> one_s, quad_s;
  for (int i = 0; i < std::max(repeats, 1); ++i) {
    auto t0 = std::chrono::steady_clock::now();
    const SlarSimulation sim = simulate_slar(town.scene, single, *sigma0, options);
    (void)coherent_sar_intensity(sim, 1);
    one_s.push_back(seconds_since(t0));
    t0 = std::chrono::steady_clock::now();
    const std::vector<SlarSimulation> sims =
        simulate_quad_pol_channels(town.scene, quad, *sigma0, options);
    (void)form_quad_pol({&sims[0], &sims[1], &sims[2]}, shapes, options.targets, 1);
    quad_s.push_back(seconds_since(t0));
  }
  omp_set_num_threads(threads_before);
  const double t1 = median(one_s), t4 = median(quad_s);
  fmt::print(
      "\nquad-pol coherent SAR (data/scenes/town.toml, {} targets, 2 threads, simulation only): "
      "single-pol HH {:.1f} ms; HH, HV, VH, VV {:.1f} ms = {:.2f} x single-pol (goal <= 3)\n",
      options.targets.size(), 1e3 * t1, 1e3 * t4, t4 / t1);
  fmt::print("quad_pol_over_single={:.3f}\n", t4 / t1);
}

}  // namespace ris::app
