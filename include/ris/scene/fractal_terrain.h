// Seeded fractal relief: mountain-like ground for shadow and layover, which
// the small real DEMs lack (docs/terrain.md).
//
// Heights are fractional Brownian motion made by spectral synthesis (Saupe,
// "Algorithms for random fractals", in Peitgen & Saupe (eds.), The Science of
// Fractal Images, 1988, algorithm SpectralSynthesisFM2D): Gaussian Fourier
// coefficients with amplitude |k|^-(H+1), i.e. power spectrum |k|^-(2H+2),
// transformed back with an inverse FFT (KISS FFT) on a grid twice the scene's
// size in each direction, of which the scene is one quarter (so opposite
// edges are not forced to match, as they would be on the FFT's periodic
// grid). The Hurst exponent H in (0, 1) sets the roughness: the height
// difference over a distance h grows as h^H (variogram ~ h^(2H)); H near 1
// gives smooth hills, near 0 rough ground. The field is then scaled so its
// lowest cell is at base_m and its highest at base_m + relief_m.
//
// Land-cover patches (optional) are Voronoi cells of jittered seed points
// about patch_size_m apart (Worley 1996), each taking one of the given
// categories at random.
//
// Every random number comes from the counter-based generator
// (ris/util/counter_rng.h) keyed by (seed, row, col): the same seed gives the
// same scene on any number of threads.
//
// Example:
//   ris::FractalParams p;
//   p.rows = p.cols = 512; p.cell_m = 30; p.relief_m = 1500; p.hurst = 0.8; p.seed = 7;
//   ris::Scene s = ris::fractal_terrain(p);
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ris/scene/scene.h"

namespace ris {

struct FractalParams {
  int rows = 512;
  int cols = 512;
  double cell_m = 30.0;      // square cells
  double relief_m = 1000.0;  // highest minus lowest elevation
  double base_m = 0.0;       // lowest elevation
  double hurst = 0.8;        // H in (0, 1)
  std::uint64_t seed = 1;
  std::uint16_t category = 0;                   // every cell, when no patches
  std::vector<std::uint16_t> patch_categories;  // patches drawn from these
  double patch_size_m = 0.0;                    // mean patch spacing (> 0 with patches)
  std::string source = "fractal";               // for messages ("--hurst")
};

// Throws InputError (naming the option) for out-of-range parameters, and
// refuses a grid too large for memory.
Scene fractal_terrain(const FractalParams& params);

// The patch categories of `count` points (x0_m + i dx_m, y_m) (scene metres,
// in the local frame of Scene::flat: south-west corner at 0, 0);
// p.patch_categories not empty. Per row of points, so a streamed generator
// (ris/scene/fractal_noise.h) paints the same patches.
void fractal_patch_row(const FractalParams& p, double y_m, double x0_m, double dx_m, int count,
                       std::uint16_t* category);

// Whether fractal_terrain's spectral synthesis fits in memory for p's size
// (else it refuses; ris/scene/fractal_noise.h streams instead).
bool spectral_synthesis_fits(const FractalParams& p);

// Throws InputError (naming the option) for out-of-range parameters.
void check_fractal_params(const FractalParams& p);

// The experimental variogram exponent: least-squares slope of
// log(mean (z(x+h) - z(x))^2) against log h for h = min_lag, 2 min_lag, ...
// up to max_lag cells along rows and columns, halved: an estimate of H. On a
// synthesised field it matches H between about 4 cells and a tenth of the
// scene (8 cells for H < 0.3); below, the grid's Nyquist cut-off smooths the field, above, the
// finite grid flattens it. For tests and `ris scene fractal` statistics.
double estimate_hurst(const Scene& scene, int min_lag, int max_lag);

}  // namespace ris
