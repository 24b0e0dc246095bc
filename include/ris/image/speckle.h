// Fading (speckle): a pixel built from N independent samples fluctuates
// about its mean power P (seed section 2.1; MODEL.md section 3, "Fading").
// The observed power is P * Y with
//
//   exact (default): Y ~ Gamma(N, 1/N), mean 1, variance 1/N: the law of
//     N-look intensity for fully developed speckle (the seed's "chi-squared
//     distribution with 2N degrees of freedom", normalised to mean 1). N may
//     be non-integer. Drawn by Marsaglia and Tsang's method (ACM TOMS 26(3),
//     2000) over ziggurat normals, boosted by U^(1/N) for N < 1.
//   seed (equation 21): Y = max(kSeedFadingFloor, 1 + RN / sqrt(N)), RN a
//     standard normal (ziggurat). In greytones this is the seed's
//     G_fad = (255/X) gamma log10(1 + RN / sqrt(N)) exactly, because
//     GreytoneMap maps P * Y to G(P) + (255/X) gamma log10(Y). The floor
//     (0.01, i.e. -20 dB: black on any film with X / gamma <= 2) stands in for
//     the logarithm of a non-positive number. Statistics (Z ~ N(0,1),
//     a = (floor - 1) sqrt(N), Phi/phi the normal CDF/density):
//       E[Y]   = floor Phi(a) + (1 - Phi(a)) + phi(a) / sqrt(N)
//       E[Y^2] = floor^2 Phi(a) + (1 - Phi(a)) + 2 phi(a) / sqrt(N)
//                + ((1 - Phi(a)) + a phi(a)) / N
//     so for N = 1: mean 1.085, standard deviation 0.865 (the clamp biases a
//     single-look image bright by 8.5% and puts 16% of its pixels at the
//     floor); N = 4: mean 1.0045, sd 0.489; for N >= 10 the clamp is
//     negligible (mean 1 + 8e-5, sd within 0.1% of 1/sqrt(N)).
//
// Randomness: the factor of pixel (line, bin) comes from CounterRng keyed by
// (seed, bin, line) (ris/util/counter_rng.h), so the speckled image is the
// same bytes for any thread count, tiling or order. Adjacent azimuth lines
// are independent here even when the footprint spans several lines, as in
// the seed.
//
// Example:
//   std::vector<double> looks(bins);   // N per range bin
//   for (int k = 0; k < bins; ++k) looks[k] = ris::independent_samples(radar, range.centre_m(k));
//   std::vector<float> speckled = img.mean_power_w;
//   if (radar.switches.fading) ris::apply_fading(speckled, lines, bins, looks, radar.fading, seed);
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "ris/sensor/radar_params.h"
#include "ris/util/counter_rng.h"
#include "ris/util/ziggurat_normal.h"

namespace ris {

inline constexpr double kSeedFadingFloor = 0.01;

// Gamma(shape, 1) by Marsaglia and Tsang (2000); shape > 0. The normals come
// from the ziggurat (ris/util/ziggurat_normal.h) and the acceptance test's
// uniform from one 32-bit word: usually one Philox block per variate. The
// shape's constants are set up once (apply_fading: once per range bin).
class GammaSampler {
 public:
  explicit GammaSampler(double shape) : shape_(shape) {
    if (shape < 1.0) shape += 1.0;  // boosted below: Gamma(a) = Gamma(a + 1) U^(1/a)
    d_ = shape - 1.0 / 3.0;
    c_ = 1.0 / std::sqrt(9.0 * d_);
  }
  double shape() const { return shape_; }
  double d() const { return d_; }  // shape (+ 1 below 1) - 1/3
  double c() const { return c_; }  // 1 / sqrt(9 d)

  double operator()(CounterRng& rng, const ZigguratTables& zig) const {
    double boost = 1.0;
    // Gamma(a) = Gamma(a + 1) U^(1/a) (Marsaglia and Tsang, section 6).
    if (shape_ < 1.0) boost = std::pow(rng.uniform(), 1.0 / shape_);
    for (;;) {
      double x = 0.0, v = 0.0;
      do {
        x = ziggurat_normal(rng, zig);
        v = 1.0 + c_ * x;
      } while (v <= 0.0);
      v = v * v * v;
      const double u = rng.uniform32();
      const double x2 = x * x;
      if (u < 1.0 - 0.0331 * x2 * x2) return boost * d_ * v;
      if (std::log(u) < 0.5 * x2 + d_ * (1.0 - v + std::log(v))) return boost * d_ * v;
    }
  }

 private:
  double shape_, d_ = 0.0, c_ = 0.0;
};

inline double gamma_variate(CounterRng& rng, double shape) {
  return GammaSampler(shape)(rng, ziggurat_tables());
}

// The fading factor Y of one pixel (see above); looks = N > 0.
inline double fading_factor(FadingLaw law, double looks, std::uint64_t seed, std::uint32_t line,
                            std::uint32_t bin) {
  CounterRng rng(seed, bin, line, CounterRng::kFadingStream);
  if (law == FadingLaw::exact_gamma) return gamma_variate(rng, looks) / looks;
  const double y = 1.0 + ziggurat_normal(rng, ziggurat_tables()) / std::sqrt(looks);
  return y > kSeedFadingFloor ? y : kSeedFadingFloor;
}

// Fading prepared for one image, applied a line at a time: the kernel of
// apply_fading and of the fused render (ris/sim/slar_simulation.h). The
// per-bin constants (the Gamma sampler's, sqrt(N)) are set up once; each
// line's first Philox blocks are computed for 64 bins at once
// (philox_first_blocks, vectorised). Most pixels need no more than that
// block: the ziggurat's common case (two words) and, for the exact law with
// N >= 1, Marsaglia and Tsang's squeeze or logarithmic test (the third word)
// decide in registers. Any other pixel (the ziggurat's wedge or tail,
// v <= 0, a rejected first try, N < 1) is drawn again from its own stream by
// GammaSampler / ziggurat_normal, which make the same draws. The same bytes
// as fading_factor per pixel (tested).
class FadingField {
 public:
  // looks_per_bin: N per range bin, each finite and > 0.
  FadingField(std::span<const double> looks_per_bin, FadingLaw law, std::uint64_t seed);
  int bins() const { return static_cast<int>(looks_.size()); }
  // Multiplies row[0, bins()) of image line `line` by its fading factors;
  // NaN and non-positive pixels are left as they are.
  void apply_line(float* row, int line) const;

 private:
  std::vector<double> looks_, sqrt_looks_;
  std::vector<GammaSampler> gamma_;
  std::vector<std::uint8_t> squeeze_in_registers_;  // per bin: N >= 1 (no boost draw)
  // Per bin, for the vectorised draw: the Gamma sampler's c (NaN where N < 1,
  // which sends every such pixel to the scalar path) and d.
  std::vector<double> squeeze_c_, squeeze_d_;
  FadingLaw law_;
  std::uint64_t seed_;
  const ZigguratTables* zig_;
};

// Multiplies each pixel of a lines x bins power raster (row = azimuth line,
// column = range bin) by its fading factor, N = looks_per_bin[bin]. NaN and
// non-positive pixels are left as they are. Parallel over lines (OpenMP);
// identical bytes for any thread count. first_line: the image line of the
// raster's first row (a block of a streamed image, ris/sim/slar_stream.h).
void apply_fading(std::span<float> power_w, int lines, int bins,
                  std::span<const double> looks_per_bin, FadingLaw law, std::uint64_t seed,
                  int first_line = 0);

}  // namespace ris
