#include "ris/geometry/terrain_line.h"

#if defined(__linux__)
#include <sys/mman.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <mutex>
#include <new>
#include <tuple>
#include <vector>

#include "kernels/gather/terrain_sampler_kernels.h"
#include "kernels/simd/cpu.h"
#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"

namespace ris {

namespace {

// One freed texel array kept for the next (one slot, the largest wins):
// repeated simulations in one process (the benchmark, a study's runs, an
// interactive session) then reuse it instead of faulting it in again, as
// keep_freed_memory_for_reuse (ris/util/memory_reuse.h) does for blocks up
// to 32 MiB. The array stays resident between runs, no more than the
// largest run's peak.
struct SpareTexels {
  std::mutex mutex;
  TerrainTexel* p = nullptr;
  std::size_t bytes = 0;
  ~SpareTexels() { std::free(p); }
};

SpareTexels& spare_texels() {
  static SpareTexels s;
  return s;
}

constexpr std::size_t kHugePage = std::size_t{2} << 20;

// The allocation size of n texels: whole 2 MiB pages.
std::size_t texel_bytes(std::size_t n) {
  const std::size_t bytes = std::max<std::size_t>(n * sizeof(TerrainTexel), 1);
  return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}

// n texels, uninitialised: the spare array when it is large enough, else
// 2 MiB-aligned and (Linux) advised to be backed by transparent huge pages
// where the kernel allows it ("madvise" mode), so that the first touch
// faults in 2 MiB at a time instead of 4 KiB (on this machine's virtual
// CPUs a 64 MB array's 16,000 small faults cost ~40 ms, more than building
// the texels). Contents and results do not depend on either.
TerrainTexel* allocate_texels(std::size_t n) {
  const std::size_t bytes = texel_bytes(n);
  {
    SpareTexels& spare = spare_texels();
    const std::lock_guard<std::mutex> lock(spare.mutex);
    if (spare.p != nullptr && spare.bytes >= bytes) {
      TerrainTexel* p = spare.p;
      spare.p = nullptr;
      spare.bytes = 0;
      return p;
    }
  }
  void* p = std::aligned_alloc(kHugePage, bytes);
  if (p == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  (void)madvise(p, bytes, MADV_HUGEPAGE);  // advice only: ignore failure
#endif
  return static_cast<TerrainTexel*>(p);
}

}  // namespace

void TerrainTexelsFree::operator()(TerrainTexel* p) const {
  if (p == nullptr) return;
  SpareTexels& spare = spare_texels();
  const std::lock_guard<std::mutex> lock(spare.mutex);
  // Keep the larger of this array and the spare (bytes: at least this
  // array's size), free the other.
  if (bytes > spare.bytes) {
    std::swap(p, spare.p);
    spare.bytes = bytes;
  }
  std::free(p);
}

TerrainTexels terrain_texels(const Scene& scene, SamplerKernel kernel) {
  const bool wide = kernel == SamplerKernel::best && cpu_has_avx512();
  TerrainTexels t;
  t.rows = scene.rows;
  t.cols = scene.cols;
  // Not zeroed: every texel is written below.
  t.texel = std::unique_ptr<TerrainTexel[], TerrainTexelsFree>(
      allocate_texels(t.size()), TerrainTexelsFree{texel_bytes(t.size())});
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const auto cols = static_cast<std::size_t>(scene.cols);
  const std::vector<float> no_z(cols, 0.0f);
  const std::vector<std::uint8_t> no_valid(cols, 0);
  const auto edge = [&](int r, int c) {
    const std::size_t i = scene.index(r, c);
    TerrainTexel& x = t.texel[i];
    x.category = static_cast<float>(scene.category[i]);
    if (!scene.valid[i]) {
      x.height_m = x.dz_dx = x.dz_dy = nan;
      return;
    }
    x.height_m = scene.elevation_m[i];
    std::tie(x.dz_dx, x.dz_dy) = cell_slope(scene, r, c);
  };
#pragma omp parallel for schedule(static)
  for (int r = 0; r < scene.rows; ++r) {
    const std::size_t row = scene.index(r, 0);
    const bool south = r + 1 < scene.rows, north = r > 0;
    kernels::texel_row(wide, scene.cols, scene.dx_m, scene.dy_m, &scene.elevation_m[row],
                       &scene.valid[row], &scene.category[row],
                       south ? &scene.elevation_m[row + cols] : no_z.data(),
                       south ? &scene.valid[row + cols] : no_valid.data(),
                       north ? &scene.elevation_m[row - cols] : no_z.data(),
                       north ? &scene.valid[row - cols] : no_valid.data(), &t.texel[row]);
    edge(r, 0);
    if (scene.cols > 1) edge(r, scene.cols - 1);
  }
  return t;
}

GridLine grid_line(const Scene& scene, double x0_m, double y0_m, double dir_x, double dir_y,
                   double first_u_m, double step_m) {
  GridLine l;
  std::tie(l.col0, l.row0) =
      scene.grid_from_world(x0_m + first_u_m * dir_x, y0_m + first_u_m * dir_y);
  // Rows grow southwards (-y).
  l.dcol = step_m * dir_x / scene.dx_m;
  l.drow = -step_m * dir_y / scene.dy_m;
  return l;
}

namespace {

// The first j in [0, n) where a predicate that is false and then true
// holds (n when none), by bisection.
template <typename Pred>
int first_true(int n, Pred pred) {
  int lo = 0, hi = n;
  while (lo < hi) {
    const int mid = lo + (hi - lo) / 2;
    if (pred(mid))
      hi = mid;
    else
      lo = mid + 1;
  }
  return lo;
}

}  // namespace

std::pair<int, int> inside_samples(const GridLine& line, int rows, int cols, int samples) {
  // Each coordinate a(j) = a0 + j da is monotone in j in floating point too
  // (each rounding is), so each of the four bounds 0 <= a(j) <= n holds on a
  // prefix or a suffix of the samples: bisect for its end. Exact, whatever
  // the rounding of an analytic intersection would be (a line along an edge,
  // a step of 1e-17 cells), in about 4 log2(samples) evaluations.
  int begin = 0, end = samples;
  const auto bound = [&](auto a, double da, double n) {
    const auto ge0 = [&](int j) { return a(j) >= 0.0; };
    const auto le_n = [&](int j) { return a(j) <= n; };
    if (da > 0.0) {
      begin = std::max(begin, first_true(samples, ge0));
      end = std::min(end, first_true(samples, [&](int j) { return !le_n(j); }));
    } else if (da < 0.0) {
      begin = std::max(begin, first_true(samples, le_n));
      end = std::min(end, first_true(samples, [&](int j) { return !ge0(j); }));
    } else if (!(ge0(0) && le_n(0))) {
      end = 0;  // along this axis, outside (or NaN)
    }
  };
  bound([&](int j) { return line.col(j); }, line.dcol, cols);
  bound([&](int j) { return line.row(j); }, line.drow, rows);
  if (begin >= end) return {0, 0};
  return {begin, end};
}

void sample_terrain_line(const TerrainTexels& tex, const GridLine& line, int begin, int end,
                         const SampledTerrain& out, SamplerKernel kernel) {
  static_assert(sizeof(TerrainTexel) == 4 * sizeof(float));
  const auto* t = reinterpret_cast<const float*>(tex.texel.get());
  kernels::sample_span(kernel == SamplerKernel::best && cpu_has_avx512(), t, tex.rows, tex.cols,
                       line, begin, end, out);
}

}  // namespace ris
