#include "ris/scene/fractal_noise.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <limits>

#include "ris/util/counter_rng.h"
#include "ris/util/error.h"

namespace ris {

namespace {

constexpr std::uint32_t kNoiseStream = 0x46524e00u;  // "FRN\0" + octave

inline double smoothstep(double t) {
  return t * t * (3.0 - 2.0 * t);
}

// The lattice value at (iy, ix) of an octave, uniform in [-1, 1].
inline double lattice(std::uint64_t seed, int octave, int iy, int ix) {
  CounterRng rng(seed, static_cast<std::uint32_t>(iy), static_cast<std::uint32_t>(ix),
                 kNoiseStream + static_cast<std::uint32_t>(octave));
  return 2.0 * rng.uniform() - 1.0;
}

}  // namespace

struct FractalNoise::Cache {
  struct Octave {
    int iy = INT_MIN;
    std::vector<double> lo, hi;  // lattice rows iy and iy + 1
    std::vector<double> weight;  // smoothstep at (k + 1/2) / w, k < w
  };
  std::vector<Octave> octaves;
};

FractalNoise::FractalNoise(const FractalParams& params) : p_(params) {
  check_fractal_params(p_);
  const int side = std::max(p_.rows, p_.cols);
  for (double w = 2.0;; w *= 2.0) {
    wavelength_.push_back(w);
    amplitude_.push_back(std::pow(w, p_.hurst));
    if (w >= side) break;
  }
  // Scale from a sample: every 16th row and the last.
  std::vector<int> sample;
  for (int r = 0; r < p_.rows; r += 16) sample.push_back(r);
  if ((p_.rows - 1) % 16 != 0) sample.push_back(p_.rows - 1);
  Cache cache;
  std::vector<double> z(static_cast<std::size_t>(p_.cols));
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int r : sample) {
    raw_row(r, z.data(), cache);
    for (double v : z) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  lo_ = lo;
  scale_ = hi > lo ? p_.relief_m / (hi - lo) : 0.0;
}

void FractalNoise::raw_row(int r, double* out, Cache& cache) const {
  const int cols = p_.cols;
  const int n_oct = static_cast<int>(wavelength_.size());
  cache.octaves.resize(static_cast<std::size_t>(n_oct));
  std::fill(out, out + cols, 0.0);
  for (int o = 0; o < n_oct; ++o) {
    const double w = wavelength_[static_cast<std::size_t>(o)];
    const double amp = amplitude_[static_cast<std::size_t>(o)];
    // Cells sit at (k + 1/2) / w of a lattice interval (w a power of two):
    // the same smoothstep weights in every interval, along x and y.
    const int wi = static_cast<int>(w);
    const int iy = r / wi;
    const double ty = smoothstep((r % wi + 0.5) / w);
    const int nx = (cols - 1) / wi + 2;  // lattice columns used
    Cache::Octave& c = cache.octaves[static_cast<std::size_t>(o)];
    const std::size_t nxs = static_cast<std::size_t>(nx);
    if (c.iy != iy) {
      // Rows go down one lattice row at a time: the old lower row is the new upper one.
      if (c.iy == iy - 1 && c.hi.size() == nxs) {
        c.lo.swap(c.hi);
      } else {
        c.lo.resize(nxs);
        for (int ix = 0; ix < nx; ++ix)
          c.lo[static_cast<std::size_t>(ix)] = lattice(p_.seed, o, iy, ix);
      }
      c.hi.resize(nxs);
      for (int ix = 0; ix < nx; ++ix)
        c.hi[static_cast<std::size_t>(ix)] = lattice(p_.seed, o, iy + 1, ix);
      c.iy = iy;
      c.weight.resize(static_cast<std::size_t>(wi));
      for (int k = 0; k < wi; ++k)
        c.weight[static_cast<std::size_t>(k)] = smoothstep((k + 0.5) / w);
    }
    const double* wt = c.weight.data();
    for (int ix = 0; ix * wi < cols; ++ix) {
      const std::size_t i = static_cast<std::size_t>(ix);
      const double a = amp * (c.lo[i] + ty * (c.hi[i] - c.lo[i]));
      const double b = amp * (c.lo[i + 1] + ty * (c.hi[i + 1] - c.lo[i + 1]));
      double* o_ = out + ix * wi;
      const int n = std::min(wi, cols - ix * wi);
      for (int k = 0; k < n; ++k) o_[k] += a + wt[k] * (b - a);
    }
  }
}

void FractalNoise::rows(int row0, int count, float* elevation_m, std::uint16_t* category) const {
  RIS_CHECK(row0 >= 0 && count >= 0 && row0 + count <= p_.rows);
  const std::size_t cols = static_cast<std::size_t>(p_.cols);
  // The local frame of Scene::flat (south-west corner at 0, 0), as fractal_terrain.
  const double top_y_m = p_.rows * p_.cell_m;
#pragma omp parallel
  {
    Cache cache;
    std::vector<double> z(cols);
#pragma omp for schedule(static)
    for (int i = 0; i < count; ++i) {
      const int r = row0 + i;
      raw_row(r, z.data(), cache);
      float* out = elevation_m + static_cast<std::size_t>(i) * cols;
      std::uint16_t* cat = category + static_cast<std::size_t>(i) * cols;
      const double y = top_y_m - (r + 0.5) * p_.cell_m;
      for (std::size_t c = 0; c < cols; ++c) {
        const double h = std::clamp((z[c] - lo_) * scale_, 0.0, p_.relief_m);
        out[c] = static_cast<float>(p_.base_m + h);
      }
      if (p_.patch_categories.empty()) {
        std::fill(cat, cat + cols, p_.category);
      } else {
        fractal_patch_row(p_, y, 0.5 * p_.cell_m, p_.cell_m, p_.cols, cat);
      }
    }
  }
}

}  // namespace ris
