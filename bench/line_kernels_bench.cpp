// Google Benchmark kernels of the per-line steps the along-axis fused path
// spends its time in, on synthetic lines shaped like `ris bench`'s 2000 x
// 2000 scene (2000 elements over 488 range bins, rough terrain): image
// formation of a line (form_line_profile, src/image/slar_element.h) and the
// cast-shadow and layover scans (mark_shadow_and_layover). Items per second
// are elements. BM_LineFormProfile/2/x: the same line sampled at half steps
// (4000 elements over the 488 bins), as an oblique track samples its lines
// (MODEL.md section 2); /x/1 with a gaussian elevation pattern, /x/0 with
// a uniform one (the seed's radars, `ris bench`: no gain lookups).
//
//   build/bench/ris_bench_kernels --benchmark_filter=Line
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "kernels/image/slar_element.h"
#include "ris/backscatter/library.h"
#include "ris/geometry/line_scan.h"
#include "ris/util/units.h"

namespace {

constexpr int kSamples = 2000;
constexpr int kBins = 488;
constexpr double kAltitude = 12192.0, kFirstU = 33500.0, kStep = 6.096;

// A rough line seen from kAltitude: heights, slant ranges, element ends,
// angles; flags from the scans.
// `split` samples per kStep (1: along a grid axis; 2: an oblique track's
// half steps), over the same ground.
struct SyntheticLine {
  int samples;
  std::vector<float> height, range, near_end, far_end, dh_du, incidence, local, area;
  std::vector<std::uint16_t> category;
  std::vector<std::uint8_t> flags;
  double near_m = 0.0, bin_m = 0.0;
  explicit SyntheticLine(int split = 1)
      : samples(kSamples * split),
        height(static_cast<std::size_t>(samples)),
        range(height.size()),
        near_end(height.size()),
        far_end(height.size()),
        dh_du(height.size(), 0.0f),
        incidence(height.size()),
        local(height.size()),
        area(height.size()),
        category(height.size()),
        flags(height.size(), 0) {
    std::mt19937 rng(3);
    std::normal_distribution<double> step(0.0, 3.0 / std::sqrt(double(split)));
    const double du = kStep / split;
    double z = 500.0;
    for (std::size_t j = 0; j < height.size(); ++j) {
      z += step(rng);
      const double u = kFirstU + double(j) * du;
      height[j] = static_cast<float>(z);
      range[j] = static_cast<float>(std::hypot(u, kAltitude - z));
      incidence[j] = static_cast<float>(std::atan2(u, kAltitude - z));
      local[j] = incidence[j] + static_cast<float>(0.1 * step(rng) / 3.0);
      area[j] = static_cast<float>(du * kStep);
      category[j] = static_cast<std::uint16_t>(1 + j / static_cast<std::size_t>(200 * split));
    }
    ris::LineSamples l{
        samples,         kFirstU,        du,           kAltitude,   height.data(), range.data(),
        near_end.data(), far_end.data(), dh_du.data(), flags.data()};
    ris::line_element_ends(l);
    ris::mark_shadow_and_layover(l);
    near_m = std::hypot(kFirstU, kAltitude) - 300.0;
    bin_m = (std::hypot(kFirstU + kSamples * kStep, kAltitude) + 300.0 - near_m) / kBins;
  }
};

void BM_LineFormProfile(benchmark::State& state) {
  const SyntheticLine line(static_cast<int>(state.range(0)));
  const auto sigma0 = ris::load_sigma0_source(ris::default_sigma0_library_path());
  std::vector<std::uint16_t> cats;
  for (std::uint16_t c = 1; c <= 10; ++c) cats.push_back(c);
  const ris::Sigma0Lut lut =
      ris::Sigma0Lut::build(*sigma0, {9.4e9, ris::Polarisation::HH}, cats, "bench");
  ris::SlarImagingParams p;
  p.range = {line.near_m, line.bin_m, kBins};
  p.transmit_power_w = 1e5;
  p.wavelength_m = 0.032;
  p.peak_gain = 1000.0;
  if (state.range(1) != 0) {
    p.elevation_gain = [](double beta) { return std::exp(-std::pow((beta - 1.3) / 0.3, 2)); };
  }
  const ris::TwoWayGainTable gain2(p.elevation_gain, p.peak_gain, "bench");
  const ris::detail::SlarElementContext ctx = ris::detail::element_context(p, gain2, lut, kBins);
  ris::detail::LineElementScratch scratch(line.samples, kBins);
  std::vector<std::uint8_t> touch(kBins);
  std::vector<std::uint16_t> mapped(kBins), visible(kBins);
  std::vector<double> power(kBins), area(kBins);
  const ris::detail::LineElements e{
      line.samples,         line.flags.data(),   line.range.data(),
      line.near_end.data(), line.far_end.data(), line.incidence.data(),
      line.local.data(),    line.area.data(),    line.category.data()};
  for (auto _ : state) {
    std::fill(mapped.begin(), mapped.end(), 0);
    std::fill(visible.begin(), visible.end(), 0);
    const ris::detail::LineElementTally t = ris::detail::form_line_profile(
        ctx, e, scratch, {touch.data(), mapped.data(), visible.data(), power.data(), area.data()},
        nullptr);
    benchmark::DoNotOptimize(t.in_swath);
    benchmark::DoNotOptimize(power.data());
  }
  state.SetItemsProcessed(state.iterations() * line.samples);
}

void BM_LineShadowAndLayover(benchmark::State& state) {
  SyntheticLine line;
  const std::vector<std::uint8_t> flags = line.flags;
  for (auto _ : state) {
    for (std::size_t j = 0; j < flags.size(); ++j) {
      line.flags[j] = flags[j] & (ris::sample_flag::kNoData | ris::sample_flag::kUnseen);
    }
    ris::mark_shadow_and_layover({kSamples, kFirstU, kStep, kAltitude, line.height.data(),
                                  line.range.data(), line.near_end.data(), line.far_end.data(),
                                  line.dh_du.data(), line.flags.data()});
    benchmark::DoNotOptimize(line.flags.data());
  }
  state.SetItemsProcessed(state.iterations() * kSamples);
}

}  // namespace

BENCHMARK(BM_LineFormProfile)->Args({1, 1})->Args({2, 1})->Args({2, 0});
BENCHMARK(BM_LineShadowAndLayover);
