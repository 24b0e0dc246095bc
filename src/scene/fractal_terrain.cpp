#include "ris/scene/fractal_terrain.h"

#include <fmt/format.h>
#include <kiss_fft.h>
#include <kiss_fftnd.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "ris/util/counter_rng.h"
#include "ris/util/error.h"

namespace ris {

namespace {

// Counter-based streams (ris/util/counter_rng.h), keyed by (seed, row, col).
constexpr std::uint32_t kHeightStream = 0x46524800u;  // "FRH\0": Fourier coefficients
constexpr std::uint32_t kPatchStream = 0x46525000u;   // "FRP\0": patch seeds

void check_params(const FractalParams& p) {
  const auto fail = [&](const std::string& key, const std::string& what) {
    throw InputError(p.source, key, what);
  };
  if (p.rows < 2 || p.cols < 2) {
    fail("--size", fmt::format("expected at least 2 x 2 cells, got {} x {}", p.cols, p.rows));
  }
  if (!(p.cell_m > 0.0) || !std::isfinite(p.cell_m)) {
    fail("--cell-size", fmt::format("expected a positive cell size, got {} m", p.cell_m));
  }
  if (!(p.relief_m >= 0.0) || !std::isfinite(p.relief_m)) {
    fail("--relief", fmt::format("expected a relief >= 0, got {} m", p.relief_m));
  }
  if (!std::isfinite(p.base_m)) fail("--base", "expected a finite base elevation");
  if (!(p.hurst > 0.0 && p.hurst < 1.0)) {
    fail("--hurst", fmt::format("expected a Hurst exponent in (0, 1), got {}", p.hurst));
  }
  if (p.category > kMaxCategory) fail("--category", "category id out of range");
  if (!p.patch_categories.empty() && !(p.patch_size_m > 0.0)) {
    fail("--patch-size", "expected a positive patch size with patch categories");
  }
  // Patches finer than a cell would give each cell an unrelated category
  // (noise, not patches), and the patch seeds of a row grow as the extent
  // over the patch size: 1 mm once hung the command.
  if (!p.patch_categories.empty() && !(p.patch_size_m >= p.cell_m)) {
    fail("--patch-size", fmt::format("patches of {:g} m are smaller than a cell ({:g} m): each "
                                     "cell would get an unrelated category; expected at least "
                                     "the cell size",
                                     p.patch_size_m, p.cell_m));
  }
}

// The smallest n >= target whose only prime factors are 2, 3 and 5 (fast
// sizes for the FFT).
int fast_fft_size(int target) {
  for (int n = std::max(target, 1);; ++n) {
    int m = n;
    for (int f : {2, 3, 5})
      while (m % f == 0) m /= f;
    if (m == 1) return n;
  }
}

// Spectral synthesis of fBm on a periodic grid_rows x grid_cols grid: the
// real part of the inverse FFT of complex Gaussian coefficients with
// amplitude |k|^-(H+1) (Saupe 1988, SpectralSynthesisFM2D). The real part of
// such a field has the same power spectrum shape, so Hermitian symmetry is not
// needed.
std::vector<float> spectral_fbm(int grid_rows, int grid_cols, double hurst, std::uint64_t seed) {
  const std::size_t n = static_cast<std::size_t>(grid_rows) * static_cast<std::size_t>(grid_cols);
  std::vector<kiss_fft_cpx> spectrum(n), field(n);
  const double exponent = -(hurst + 1.0);
#pragma omp parallel for schedule(static)
  for (int ky = 0; ky < grid_rows; ++ky) {
    // Signed frequencies in cycles per cell.
    const double fy = double(ky <= grid_rows / 2 ? ky : ky - grid_rows) / grid_rows;
    for (int kx = 0; kx < grid_cols; ++kx) {
      const double fx = double(kx <= grid_cols / 2 ? kx : kx - grid_cols) / grid_cols;
      const double f2 = fx * fx + fy * fy;
      kiss_fft_cpx& a = spectrum[static_cast<std::size_t>(ky) * grid_cols + kx];
      if (f2 == 0.0) {
        a.r = a.i = 0.0f;  // the mean height is set by the scaling afterwards
        continue;
      }
      const double amp = std::pow(f2, 0.5 * exponent);
      CounterRng rng(seed, static_cast<std::uint32_t>(ky), static_cast<std::uint32_t>(kx),
                     kHeightStream);
      a.r = static_cast<float>(amp * rng.normal());
      a.i = static_cast<float>(amp * rng.normal());
    }
  }
  const int dims[2] = {grid_rows, grid_cols};
  kiss_fftnd_cfg cfg = kiss_fftnd_alloc(dims, 2, 1, nullptr, nullptr);
  RIS_CHECK(cfg != nullptr);
  kiss_fftnd(cfg, spectrum.data(), field.data());
  kiss_fft_free(cfg);
  std::vector<float> z(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = field[i].r;
  return z;
}

void paint_patches(Scene& s, const FractalParams& p) {
#pragma omp parallel for schedule(static)
  for (int r = 0; r < s.rows; ++r) {
    const auto [x0, y] = s.cell_centre(r, 0);
    fractal_patch_row(p, y, x0, s.dx_m, s.cols, s.category.data() + s.index(r, 0));
  }
}

}  // namespace

// Voronoi patches of jittered seeds, one per patch_size square (Worley 1996).
// The seeds of the 3 x (span + 2) patch squares around a row of points are
// drawn once for the row.
void fractal_patch_row(const FractalParams& p, double y, double x0, double dx, int count,
                       std::uint16_t* out) {
  if (count <= 0) return;
  const double size = p.patch_size_m;
  const int n_cats = static_cast<int>(p.patch_categories.size());
  const auto gy = static_cast<long long>(std::floor(y / size));
  const auto gx_lo = static_cast<long long>(std::floor(std::min(x0, x0 + (count - 1) * dx) / size));
  const auto gx_hi = static_cast<long long>(std::floor(std::max(x0, x0 + (count - 1) * dx) / size));
  const long long nx = gx_hi - gx_lo + 3;
  struct Seed {
    double x, y, pick;
  };
  std::vector<Seed> seeds(static_cast<std::size_t>(3 * nx));
  for (long long jy = gy - 1; jy <= gy + 1; ++jy) {
    for (long long jx = gx_lo - 1; jx <= gx_hi + 1; ++jx) {
      // Wrapping negative indices to 32 bits keeps them distinct keys.
      CounterRng rng(p.seed, static_cast<std::uint32_t>(jy), static_cast<std::uint32_t>(jx),
                     kPatchStream);
      Seed& sd = seeds[static_cast<std::size_t>((jy - gy + 1) * nx + (jx - gx_lo + 1))];
      sd.x = (double(jx) + rng.uniform()) * size;
      sd.y = (double(jy) + rng.uniform()) * size;
      sd.pick = rng.uniform();
    }
  }
  for (int i = 0; i < count; ++i) {
    const double x = x0 + i * dx;
    const auto gx = static_cast<long long>(std::floor(x / size));
    double best = std::numeric_limits<double>::infinity();
    double best_pick = 0.0;
    for (long long jy = 0; jy < 3; ++jy) {
      for (long long jx = gx - 1; jx <= gx + 1; ++jx) {
        const Seed& sd = seeds[static_cast<std::size_t>(jy * nx + (jx - gx_lo + 1))];
        const double dist = (sd.x - x) * (sd.x - x) + (sd.y - y) * (sd.y - y);
        if (dist < best) best = dist, best_pick = sd.pick;
      }
    }
    const auto pick = std::min(static_cast<std::size_t>(best_pick * n_cats),
                               static_cast<std::size_t>(n_cats - 1));
    out[i] = p.patch_categories[pick];
  }
}

// Refuses a size whose synthesis does not fit in memory.
void check_spectral_memory(const FractalParams& p) {
  check_scene_fits_in_memory(p.rows, p.cols, p.source, "--size");
  // The synthesis grid is twice the scene each way (no forced periodicity),
  // two complex floats per cell: about 4 x 16 bytes per scene cell, checked
  // as that many scene cells' worth.
  const int grid_rows = fast_fft_size(2 * p.rows);
  const int grid_cols = fast_fft_size(2 * p.cols);
  check_scene_fits_in_memory(
      std::int64_t(grid_rows) * std::int64_t(16 / Scene::bytes_per_cell() + 1), grid_cols, p.source,
      "--size");
}

bool spectral_synthesis_fits(const FractalParams& p) {
  try {
    check_spectral_memory(p);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

void check_fractal_params(const FractalParams& p) {
  check_params(p);
}

Scene fractal_terrain(const FractalParams& p) {
  check_params(p);
  check_spectral_memory(p);
  const int grid_rows = fast_fft_size(2 * p.rows);
  const int grid_cols = fast_fft_size(2 * p.cols);
  const std::vector<float> z = spectral_fbm(grid_rows, grid_cols, p.hurst, p.seed);

  Scene s = Scene::flat(p.rows, p.cols, p.cell_m, 0.0f, p.category);
  float lo = std::numeric_limits<float>::max(), hi = -lo;
  for (int r = 0; r < p.rows; ++r) {
    for (int c = 0; c < p.cols; ++c) {
      const float v = z[static_cast<std::size_t>(r) * grid_cols + c];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  const double span = hi > lo ? double(hi) - double(lo) : 1.0;
  for (int r = 0; r < p.rows; ++r) {
    for (int c = 0; c < p.cols; ++c) {
      const double v = z[static_cast<std::size_t>(r) * grid_cols + c];
      s.elevation_m[s.index(r, c)] =
          static_cast<float>(p.base_m + p.relief_m * (v - double(lo)) / span);
    }
  }
  if (!p.patch_categories.empty()) paint_patches(s, p);
  return s;
}

double estimate_hurst(const Scene& s, int min_lag, int max_lag) {
  std::vector<double> log_h, log_g;
  for (int h = std::max(min_lag, 1); h <= max_lag && h < std::min(s.rows, s.cols); h *= 2) {
    double sum = 0.0;
    std::size_t n = 0;
    for (int r = 0; r < s.rows; ++r) {
      for (int c = 0; c < s.cols; ++c) {
        const double z = s.elevation_m[s.index(r, c)];
        if (c + h < s.cols) {
          const double dz = s.elevation_m[s.index(r, c + h)] - z;
          sum += dz * dz, ++n;
        }
        if (r + h < s.rows) {
          const double dz = s.elevation_m[s.index(r + h, c)] - z;
          sum += dz * dz, ++n;
        }
      }
    }
    log_h.push_back(std::log(double(h)));
    log_g.push_back(std::log(sum / double(n)));
  }
  RIS_CHECK(log_h.size() >= 2);
  const double k = double(log_h.size());
  double mx = 0, my = 0;
  for (std::size_t i = 0; i < log_h.size(); ++i) mx += log_h[i], my += log_g[i];
  mx /= k, my /= k;
  double sxy = 0, sxx = 0;
  for (std::size_t i = 0; i < log_h.size(); ++i) {
    sxy += (log_h[i] - mx) * (log_g[i] - my);
    sxx += (log_h[i] - mx) * (log_h[i] - mx);
  }
  return 0.5 * sxy / sxx;
}

}  // namespace ris
