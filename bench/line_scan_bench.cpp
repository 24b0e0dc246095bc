// Google Benchmark kernel of the element ends of a line (line_element_ends,
// ris/geometry/line_scan.h: two slant ranges a sample, from the heights
// halfway to its neighbours) on a rough 2000-sample line with a few no-data
// samples, shaped like `ris bench`'s. Items per second are samples.
//
//   build/bench/ris_bench_kernels --benchmark_filter=LineElementEnds
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "ris/geometry/line_scan.h"

namespace {

void BM_LineElementEnds(benchmark::State& state) {
  constexpr int kSamples = 2000;
  constexpr double kAltitude = 12192.0, kFirstU = 33500.0, kStep = 3.048;
  std::vector<float> height(kSamples), range(kSamples), near_end(kSamples), far_end(kSamples),
      dh_du(kSamples);
  std::vector<std::uint8_t> flags(kSamples, 0);
  std::mt19937 rng(3);
  std::normal_distribution<double> step(0.0, 1.5);
  double z = 500.0;
  for (std::size_t j = 0; j < height.size(); ++j) {
    const double dz = step(rng);
    z += dz;
    height[j] = static_cast<float>(z);
    dh_du[j] = static_cast<float>(dz / kStep);
    range[j] = static_cast<float>(std::hypot(kFirstU + double(j) * kStep, kAltitude - z));
    if (j % 97 == 5) flags[j] = ris::sample_flag::kNoData;
  }
  for (auto _ : state) {
    ris::line_element_ends({kSamples, kFirstU, kStep, kAltitude, height.data(), range.data(),
                            near_end.data(), far_end.data(), dh_du.data(), flags.data()});
    benchmark::DoNotOptimize(near_end.data());
    benchmark::DoNotOptimize(far_end.data());
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}
BENCHMARK(BM_LineElementEnds);

}  // namespace
