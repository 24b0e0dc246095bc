// Google Benchmark kernel of the render's greytone step alone
// (ris/image/greytone.h greytone_line: the exact threshold table, one lookup
// per pixel) over a line of speckled powers spread over ~40 dB around the
// reference, as a picture's. Items per second are pixels.
//
//   build/bench/ris_bench_kernels --benchmark_filter=GreytoneLine
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>
#include <vector>

#include "ris/image/greytone.h"
#include "ris/sensor/radar_config.h"
#include "ris/util/data_dir.h"

namespace {

void BM_GreytoneLine(benchmark::State& state) {
  constexpr int kPixels = 1 << 16;
  const ris::RadarParams radar =
      ris::load_radar((ris::data_dir() / "radars/seed-fig4-5.toml").string());
  const ris::GreytoneMap map(radar, 1e-9, 128.0);
  std::mt19937 rng(3);
  std::normal_distribution<double> db(0.0, 8.0);
  std::vector<float> power(kPixels);
  for (float& p : power) p = static_cast<float>(1e-9 * std::pow(10.0, db(rng) / 10.0));
  std::vector<std::uint8_t> mask(kPixels, 0), out(kPixels);
  for (auto _ : state) {
    ris::greytone_line(map, power.data(), mask.data(), 0xff, power.size(), out.data());
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * kPixels);
}
BENCHMARK(BM_GreytoneLine);

}  // namespace
