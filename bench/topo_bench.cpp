// Google Benchmark of `ris topo` (ris/geometry/topo.h) on the shipped
// airborne example acquisition (data/acquisitions/, L band, 12.5 km, 60 lines
// x 300 bins of 12.5 m) over a rolling 1 arc-second DEM, at 1 and 2
// threads. Items per second are DEM facets placed by geo2rdr (the DEM pass,
// the costly step); the radar pass is timed with it.
//
//   build/bench/ris_bench_kernels --benchmark_filter=Topo
#include <benchmark/benchmark.h>

#include <cmath>

#include "ris/geometry/topo.h"
#include "ris/util/data_dir.h"
#include "ris/util/units.h"

namespace {

ris::Acquisition small_airborne() {
  ris::Acquisition a = ris::read_acquisition(ris::data_dir().string() +
                                             "/acquisitions/airborne-l-band-flight-line.toml");
  a.grid.lines = 60;
  a.grid.line_interval_s = 0.1;
  a.grid.bins = 300;
  a.grid.range_spacing_m = 12.5;
  return a;
}

// Rolling hills (100 m) on 1 arc-second postings around the grid.
ris::EllipsoidalDem hills(const ris::Acquisition& a) {
  const auto f = ris::ZeroDopplerFrame(a.orbit.interpolate(a.grid.time_of_line(30)),
                                       a.grid.look_side, a.ellipsoid);
  const auto c = ris::rdr2geo(
      f, a.ellipsoid, a.grid.range_of_bin(150), [](double, double) { return 230.0; }, 230.0);
  const double half = ris::deg_to_rad(0.06), step = ris::deg_to_rad(1.0 / 3600.0);
  const int n = static_cast<int>(2 * half / step) + 1;
  ris::EllipsoidalDem d = ris::flat_ellipsoidal_dem(
      c.geodetic.lat_rad - half, c.geodetic.lat_rad - half + (n - 1) * step,
      c.geodetic.lon_rad - half, c.geodetic.lon_rad - half + (n - 1) * step, n, n, 230.0);
  for (int r = 0; r < n; ++r) {
    for (int k = 0; k < n; ++k) {
      d.height_m[static_cast<std::size_t>(r) * n + k] =
          static_cast<float>(230.0 + 50.0 * (std::sin(r * 0.05) + std::cos(k * 0.07)));
    }
  }
  return d;
}

void BM_Topo(benchmark::State& state) {
  const ris::Acquisition a = small_airborne();
  const ris::EllipsoidalDem dem = hills(a);
  ris::TopoOptions o;
  o.threads = static_cast<int>(state.range(0));
  o.oversample = 8;
  std::size_t facets = 0;
  for (auto _ : state) {
    const ris::TopoLayers t = ris::compute_topo(a, dem, o);
    facets += t.dem_facets;
    benchmark::DoNotOptimize(t.gamma_area_m2.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(facets));
}
BENCHMARK(BM_Topo)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
