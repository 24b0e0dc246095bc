// Google Benchmark kernels of the SLAR pipeline on a fractal scene
// (ris/perf/bench_setup.h): each stage alone, so a change to one stage shows
// in its own figure. Items per second are scene cells (or image pixels for
// the stages after image formation).
//
//   build/bench/ris_bench_kernels --benchmark_filter=Geometry
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "ris/backscatter/library.h"
#include "ris/backscatter/sigma0_lut.h"
#include "ris/geometry/scene_geometry_maps.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/image/slar_image.h"
#include "ris/image/speckle.h"
#include "ris/perf/bench_setup.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sim/slar_simulation.h"
#include "ris/util/data_dir.h"
#include "ris/util/float_select.h"
#include "ris/util/memory_reuse.h"
#include "ris/util/units.h"

namespace {

struct Fixture {
  ris::Scene scene;
  std::unique_ptr<ris::Sigma0Source> sigma0;
  ris::RadarParams along, oblique;
  explicit Fixture(int n)
      : scene(ris::make_bench_scene(n, n, 6.096, 7)),
        sigma0(ris::load_sigma0_source(ris::default_sigma0_library_path())) {
    const ris::RadarParams base =
        ris::load_radar((ris::data_dir() / "radars/seed-fig4-5.toml").string());
    along = ris::bench_radar(base, scene, 0.0);
    oblique = ris::bench_radar(base, scene, ris::deg_to_rad(30.0));
  }
};

const Fixture& fixture() {
  static const Fixture f(1000);
  return f;
}

const ris::RadarParams& radar_for(const benchmark::State& state) {
  return state.range(1) ? fixture().oblique : fixture().along;
}

void BM_Geometry(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const Fixture& f = fixture();
  const ris::RadarParams& radar = radar_for(state);
  const ris::Track track = ris::resolve_track(radar.track, f.scene, "bench");
  for (auto _ : state) {
    ris::SlarGeometry g = ris::compute_slar_geometry(f.scene, track, 0.0, "bench");
    benchmark::DoNotOptimize(g.flags.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(f.scene.size()));
}

void BM_EndToEnd(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const Fixture& f = fixture();
  const ris::RadarParams& radar = radar_for(state);
  for (auto _ : state) {
    ris::SlarSimulation sim = ris::simulate_slar(f.scene, radar, *f.sigma0);
    ris::SlarPictures pic = ris::render_slar(sim, 1);
    benchmark::DoNotOptimize(pic.slant_grey.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(f.scene.size()));
}

void BM_Render(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const Fixture& f = fixture();
  const ris::SlarSimulation sim = ris::simulate_slar(f.scene, radar_for(state), *f.sigma0);
  for (auto _ : state) {
    ris::SlarPictures pic = ris::render_slar(sim, 1);
    benchmark::DoNotOptimize(pic.slant_grey.data());
  }
  state.SetItemsProcessed(state.iterations() *
                          static_cast<std::int64_t>(sim.image.mean_power_w.size()));
}

// The ground-range reference height's exact median of every cell with data
// (ris/util/float_select.h, as simulate_slar calls it). Arg: threads.
void BM_MedianElevation(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const ris::Scene& scene = fixture().scene;
  const std::uint8_t* valid = scene.valid.data();
  const float* h = scene.elevation_m.data();
  for (auto _ : state) {
    const auto m = ris::median_pair_float(
        scene.elevation_m, [=](std::size_t i) { return (valid[i] != 0) & std::isfinite(h[i]); });
    benchmark::DoNotOptimize(m);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(scene.size()));
}
BENCHMARK(BM_MedianElevation)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The backscatter LUT of a run (ris/backscatter/sigma0_lut.h): the default
// library's ten categories tabulated at the bench radar's band, as
// prepare_radiometry builds it. Arg: threads.
void BM_Sigma0Lut(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const Fixture& f = fixture();
  const ris::RadarBand band{f.along.frequency_hz, f.along.polarisation};
  const std::vector<std::uint16_t> categories = f.sigma0->category_ids();
  for (auto _ : state) {
    const ris::Sigma0Lut lut = ris::Sigma0Lut::build(*f.sigma0, band, categories, "bench");
    benchmark::DoNotOptimize(lut.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(categories.size()) *
                          (ris::Sigma0Lut::kSteps + 1));
}
BENCHMARK(BM_Sigma0Lut)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The speckle alone (ris/image/speckle.h: batched Philox blocks, the common
// draw vectorised) over a 2000-line x 488-bin image, N = 1.05 (the
// figure-4-5 radar's). Args: threads, law (0 exact, 1 seed).
void BM_Fading(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  const int lines = 2000, bins = 488;
  const std::vector<double> looks(bins, 1.05);
  const ris::FadingLaw law =
      state.range(1) ? ris::FadingLaw::seed_eq21 : ris::FadingLaw::exact_gamma;
  std::vector<float> power(static_cast<std::size_t>(lines) * bins);
  for (auto _ : state) {
    std::fill(power.begin(), power.end(), 1.0f);
    ris::apply_fading(power, lines, bins, looks, law, 7);
    benchmark::DoNotOptimize(power.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(power.size()));
}
BENCHMARK(BM_Fading)->ArgsProduct({{1, 2}, {0, 1}})->Unit(benchmark::kMillisecond)->UseRealTime();

// Args: threads, oblique (0/1).
BENCHMARK(BM_Geometry)->ArgsProduct({{1, 2}, {0, 1}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EndToEnd)->ArgsProduct({{1, 2}, {0, 1}})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_Render)->ArgsProduct({{1, 2}, {0, 1}})->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  ris::keep_freed_memory_for_reuse();  // as the ris tool does
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
