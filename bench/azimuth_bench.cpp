// Google Benchmark kernel of the SLAR azimuth step alone
// (integrate_slar_azimuth: the running sums' push and the pixels' emit,
// ris/image/slar_azimuth_integrator.h) on range profiles shaped like `ris
// bench`'s oblique run (heading 30 deg: 2732 lines x 665 bins, the
// figure-4-5 radar's footprint of ~4 lines; the rotated square scene covers
// about half of the lines x bins rectangle, the rest holds no data). Items
// per second are image pixels. Arg: threads.
//
//   build/bench/ris_bench_kernels --benchmark_filter=AzimuthStep
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "ris/image/slar_image.h"

namespace {

ris::SlarLineProfiles oblique_profiles(int lines, int bins) {
  ris::SlarLineProfiles prof;
  prof.allocate(lines, bins);
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> power(0.0f, 1e-9f);
  std::uniform_int_distribution<int> touch(1, 7);
  for (int j = 0; j < lines; ++j) {
    // A square rotated by 30 deg: each line's data bins grow to the middle
    // line and shrink after it.
    const double t = double(j) / (lines - 1);
    const double half_width = (t < 0.5 ? t : 1.0 - t) * bins;
    const int lo = std::max(0, static_cast<int>(0.5 * bins - half_width));
    const int hi = std::min(bins, static_cast<int>(0.5 * bins + half_width));
    for (int b = 0; b < bins; ++b) {
      const std::size_t k = prof.index(j, b);
      const bool data = b >= lo && b < hi;
      prof.power_w[k] = data ? power(rng) : 0.0f;
      prof.area_m2[k] = data ? 37.0f : 0.0f;
      prof.touch[k] = data ? static_cast<std::uint8_t>(touch(rng)) : 0;
    }
  }
  return prof;
}

void BM_AzimuthStep(benchmark::State& state) {
  omp_set_num_threads(static_cast<int>(state.range(0)));
  constexpr int kLines = 2732, kBins = 665;
  static const ris::SlarLineProfiles prof = oblique_profiles(kLines, kBins);
  ris::SlarImagingParams p;
  p.range = {35700.0, 24.4, kBins};
  p.azimuth_beamwidth_rad = 6.8e-4;
  ris::SlarImage img;
  img.lines = kLines;
  img.bins = kBins;
  img.range = p.range;
  for (auto _ : state) {
    ris::integrate_slar_azimuth(prof, p, 6.096, img);
    benchmark::DoNotOptimize(img.mean_power_w.data());
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t{kLines} * kBins);
}
BENCHMARK(BM_AzimuthStep)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
