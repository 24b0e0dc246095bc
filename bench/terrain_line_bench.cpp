// Google Benchmark kernels of the oblique track's terrain line sampler
// (ris/geometry/terrain_line.h) on a 1000 x 1000 fractal scene, heading 30
// or 45 deg (the argument), the texels built once. Items per second are samples within the scene
// (about two per scene cell). "Hot" samples the same two lines over and over
// (texels in cache): the gap to the full run is the cost of memory.
//
//   build/bench/ris_bench_kernels --benchmark_filter=Terrain
#include <benchmark/benchmark.h>

#include <vector>

#include "ris/geometry/slar_geometry.h"
#include "ris/geometry/terrain_line.h"
#include "ris/perf/bench_setup.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/data_dir.h"
#include "ris/util/units.h"

namespace {

struct LineFixture {
  ris::Scene scene = ris::make_bench_scene(1000, 1000, 6.096, 7);
  ris::SlarGeometry g;
  ris::TerrainTexels tex;
  explicit LineFixture(double heading_deg) {
    const ris::RadarParams base =
        ris::load_radar((ris::data_dir() / "radars/seed-fig4-5.toml").string());
    const ris::RadarParams radar = ris::bench_radar(base, scene, ris::deg_to_rad(heading_deg));
    g = ris::slar_geometry_layout(scene, ris::resolve_track(radar.track, scene, "bench"), 0.0);
    tex = ris::terrain_texels(scene);
  }
};

const LineFixture& line_fixture(int heading_deg = 30) {
  if (heading_deg == 45) {
    static const LineFixture f45(45.0);
    return f45;
  }
  static const LineFixture f30(30.0);
  return f30;
}

// Samples every line (hot: lines g.lines / 2 and the next, alternately).
void run_sampler(benchmark::State& state, bool hot) {
  const LineFixture& f = line_fixture(static_cast<int>(state.range(0)));
  const auto n = static_cast<std::size_t>(f.g.samples);
  std::vector<float> h(n), gx(n), gy(n);
  std::vector<std::uint16_t> cat(n);
  std::vector<std::uint8_t> flags(n);
  std::int64_t samples = 0;
  for (auto _ : state) {
    for (int line = 0; line < f.g.lines; ++line) {
      const int l = hot ? f.g.lines / 2 + (line & 1) : line;
      const ris::SlarLineSpan span = ris::slar_line_span(f.scene, f.g, l);
      ris::sample_terrain_line(f.tex, span.grid, span.begin, span.end,
                               {h.data(), gx.data(), gy.data(), cat.data(), flags.data()});
      samples += span.end - span.begin;
    }
    benchmark::DoNotOptimize(h.data());
  }
  state.SetItemsProcessed(samples);
}

void BM_TerrainLineSampler(benchmark::State& state) {
  run_sampler(state, false);
}

void BM_TerrainLineSamplerHot(benchmark::State& state) {
  run_sampler(state, true);
}

void BM_TerrainTexels(benchmark::State& state) {
  const LineFixture& f = line_fixture();
  for (auto _ : state) {
    ris::TerrainTexels tex = ris::terrain_texels(f.scene);
    benchmark::DoNotOptimize(tex.texel.get());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(f.scene.size()));
}

BENCHMARK(BM_TerrainLineSampler)->Arg(30)->Arg(45)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TerrainLineSamplerHot)->Arg(30)->Arg(45)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TerrainTexels)->Unit(benchmark::kMillisecond);

}  // namespace
