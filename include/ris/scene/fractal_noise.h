// Fractal relief for scenes larger than memory, made a block of rows at a
// time: fractional Brownian motion approximated by a sum of octaves of value
// noise (Musgrave's fBm, in Ebert et al., "Texturing and Modeling: A
// Procedural Approach", 3rd ed., 2003, ch. 16; value noise: Perlin 1985),
//
//   z(x, y) = sum_o lambda_o^H N(x / lambda_o, y / lambda_o, o),
//
// wavelengths lambda_o = 2, 4, 8, ... cells up to the first power of two at
// least the scene's larger side, N smooth (smoothstep) bilinear
// interpolation of lattice values uniform in [-1, 1] drawn from the
// counter-based generator keyed by (seed, lattice row, lattice column,
// octave). Amplitude growing as lambda^H gives the variogram ~ h^(2H) of fBm
// with Hurst exponent H over the octaves' range. Every cell is a function of
// its position, so any block of rows can be made alone, on any thread.
//
// Spectral synthesis (ris/scene/fractal_terrain.h) is the better fBm (exact
// power spectrum, no lattice artefacts) but needs the whole grid, four times
// over, in memory; `ris scene fractal` uses this generator when that does not
// fit, or when asked (--generator noise).
//
// Scaling: heights are mapped so that the lowest and highest of a sample of
// the field (every 16th row) go to base_m and base_m + relief_m;
// the few cells beyond are clamped into that range. Patches of categories
// are those of fractal_terrain (fractal_patch_row).
//
// Example:
//   ris::FractalNoise gen(params);
//   gen.rows(r0, n, elevation.data(), category.data());  // n x params.cols
#pragma once

#include <cstdint>
#include <vector>

#include "ris/scene/fractal_terrain.h"

namespace ris {

class FractalNoise {
 public:
  // Throws InputError for out-of-range parameters (as fractal_terrain).
  explicit FractalNoise(const FractalParams& params);

  // Rows [row0, row0 + count) of the scene: elevation (metres) and category,
  // count x cols each. Parallel over rows (OpenMP); the same values on any
  // number of threads.
  void rows(int row0, int count, float* elevation_m, std::uint16_t* category) const;

 private:
  struct Cache;  // per thread: the lattice rows of each octave last used
  void raw_row(int row, double* out, Cache& cache) const;

  FractalParams p_;
  std::vector<double> wavelength_, amplitude_;  // per octave, cells
  double lo_ = 0.0, scale_ = 0.0;               // z = base + (raw - lo) * scale
};

}  // namespace ris
