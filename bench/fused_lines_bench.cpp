// Google Benchmark kernel of the fused SLAR line stage alone
// (form_slar_image_fused: geometry, image formation and scene maps per line,
// then the azimuth integration), on `ris bench`'s 2000 x 2000 fractal scene
// and radar, so that a change to the per-line compute shows without the
// scene generation and render around it. Items per second are scene cells.
// Args: threads, oblique (0/1).
//
//   build/bench/ris_bench_kernels --benchmark_filter=FusedLines/1/0
#include <benchmark/benchmark.h>
#include <omp.h>

#include <memory>

#include "ris/backscatter/library.h"
#include "ris/geometry/scene_geometry_maps.h"
#include "ris/geometry/slar_geometry.h"
#include "ris/perf/bench_setup.h"
#include "ris/sensor/radar_config.h"
#include "ris/sensor/radar_derived.h"
#include "ris/sim/radiometry_setup.h"
#include "ris/sim/slar_line_blocks.h"
#include "ris/util/data_dir.h"
#include "ris/util/units.h"

namespace {

struct FusedFixture {
  ris::Scene scene;
  std::unique_ptr<ris::Sigma0Source> sigma0;
  ris::RadarParams radar[2];
  FusedFixture()
      : scene(ris::make_bench_scene(2000, 2000, 6.096, 7)),
        sigma0(ris::load_sigma0_source(ris::default_sigma0_library_path())) {
    const ris::RadarParams base =
        ris::load_radar((ris::data_dir() / "radars/seed-fig4-5.toml").string());
    radar[0] = ris::bench_radar(base, scene, 0.0);
    radar[1] = ris::bench_radar(base, scene, ris::deg_to_rad(30.0));
  }
};

void BM_FusedLines(benchmark::State& state) {
  static const FusedFixture f;
  omp_set_num_threads(static_cast<int>(state.range(0)));
  ris::RadarParams radar = f.radar[state.range(1) ? 1 : 0];
  const ris::RadarDerived derived = ris::derive(radar);
  const ris::Track track = ris::resolve_track(radar.track, f.scene, "bench");
  const ris::SlarGeometry layout =
      ris::slar_geometry_layout(f.scene, track, radar.azimuth_line_spacing_m);
  const ris::RadiometrySetup rs =
      ris::prepare_radiometry(f.scene, radar, derived, *f.sigma0, "bench");
  for (auto _ : state) {
    ris::SlarGeometry g = layout;
    ris::SceneGeometryMaps maps;
    const ris::SlarImage img =
        ris::form_slar_image_fused(f.scene, g, maps, rs.lut, rs.imaging, "bench");
    benchmark::DoNotOptimize(img.mean_power_w.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(f.scene.size()));
}
BENCHMARK(BM_FusedLines)
    ->ArgsProduct({{1, 2}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
