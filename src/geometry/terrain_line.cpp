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

#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/util/vector_clones.h"

namespace ris {

namespace {

// Hot loops: an AVX2 clone beside the SSE2 default, the same bytes on any
// CPU (ris/util/vector_clones.h).

// One row's texels: the interior columns [1, cols - 1) in one pass of
// selects (slope_difference, no branches) that vectorises; the edge columns
// by cell_slope, the same rule with the bounds checked. zs, vs / zn, vn: the
// rows south (r + 1) and north (r - 1), or a row without data beyond the
// scene's edge.
RIS_VECTOR_CLONES void texel_row_interior(
    int cols, double dx_m, double dy_m, const float* __restrict z, const std::uint8_t* __restrict v,
    const std::uint16_t* __restrict cat, const float* __restrict zs,
    const std::uint8_t* __restrict vs, const float* __restrict zn,
    const std::uint8_t* __restrict vn, TerrainTexel* __restrict out) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int c = 1; c < cols - 1; ++c) {
    const bool ok = v[c] != 0;
    const float gx = slope_difference(v[c - 1] != 0, z[c - 1], v[c + 1] != 0, z[c + 1], z[c], dx_m);
    const float gy = slope_difference(vs[c] != 0, zs[c], vn[c] != 0, zn[c], z[c], dy_m);
    out[c].height_m = ok ? z[c] : nan;
    out[c].dz_dx = ok ? gx : nan;
    out[c].dz_dy = ok ? gy : nan;
    out[c].category = static_cast<float>(cat[c]);
  }
}

}  // namespace

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

TerrainTexels terrain_texels(const Scene& scene) {
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
    texel_row_interior(scene.cols, scene.dx_m, scene.dy_m, &scene.elevation_m[row],
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

namespace {

// Samples [begin, end) of the line into out[j - begin], a chunk of kChunk
// samples at a time in two passes:
//  1. where: bilinear_cells over the chunk (selects only, so GCC vectorises
//     it), keeping each sample's first corner, nearest cell and weights;
//  2. what: per sample, its four corner texels as 4-float vectors (height,
//     dz/dx, dz/dy, category: one 16-byte load each, no gathers) weighted by
//     the broadcast weight, the same float operations in the same corner
//     order as bilinear_terrain_sample lane by lane.
// Pass 2 replaced 13 AVX2 gathers a sample (13 lanes each of a different
// texel load, ~8 cycles a gather on this EPYC) by 4 vector loads.
constexpr int kChunk = 128;

using Float4 = float __attribute__((vector_size(16)));
using Int4 = std::int32_t __attribute__((vector_size(16)));

inline Float4 load_texel(const float* p) {
  Float4 v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

template <typename Index>
[[gnu::always_inline]] inline void sample_span(const float* __restrict tex, int rows, int cols,
                                               GridLine line, int begin, int end,
                                               float* __restrict height, float* __restrict dz_dx,
                                               float* __restrict dz_dy,
                                               std::uint16_t* __restrict category,
                                               std::uint8_t* __restrict flags) {
  // Texel k of cell i is tex[4 i + k]; the corners' offsets from the first
  // are the same for every sample (bilinear_cells' steps).
  const BilinearCells<Index> steps = bilinear_cells<Index>(rows, cols, 0.5, 0.5);
  const Index d1 = 4 * steps.step_col, d2 = 4 * steps.step_row, d3 = d2 + d1;
  alignas(32) Index first[kChunk], nearest[kChunk];
  alignas(32) float w0[kChunk], w1[kChunk], w2[kChunk], w3[kChunk];
  for (int j0 = begin; j0 < end; j0 += kChunk) {
    const int n = std::min(kChunk, end - j0);
    for (int k = 0; k < n; ++k) {
      const BilinearCells<Index> b =
          bilinear_cells<Index>(rows, cols, line.col(j0 + k), line.row(j0 + k));
      first[k] = 4 * b.cell00;
      nearest[k] = 4 * b.nearest + 3;
      w0[k] = b.weight[0];
      w1[k] = b.weight[1];
      w2[k] = b.weight[2];
      w3[k] = b.weight[3];
    }
    const int o0 = j0 - begin;
    for (int k = 0; k < n; ++k) {
      const float* const t = tex + first[k];
      // Sum of weight x value over the corners with a weight above 0, in
      // corner order (as bilinear_terrain_sample): a no-data corner's NaN
      // makes the sample no data. The product comes before the select
      // (0 x NaN is NaN).
      Float4 acc = {0.0f, 0.0f, 0.0f, 0.0f};
      const auto add = [&acc](float w, const float* p) {
        const Float4 wv = {w, w, w, w};  // a broadcast (Float4{} + w is an add)
        const Float4 product = wv * load_texel(p);
        const Int4 keep = wv > Float4{};
        acc += keep ? product : Float4{};
      };
      add(w0[k], t);
      add(w1[k], t + d1);
      add(w2[k], t + d2);
      add(w3[k], t + d3);
      const float h = acc[0];
      const bool no_data = h != h;  // NaN
      const int o = o0 + k;
      height[o] = h;
      dz_dx[o] = acc[1];
      dz_dy[o] = acc[2];
      category[o] = no_data ? std::uint16_t{0}
                            : static_cast<std::uint16_t>(static_cast<int>(tex[nearest[k]]));
      flags[o] = no_data ? sample_flag::kNoData : std::uint8_t{0};
    }
  }
}

// The sampler's clones: AVX-512 beside RIS_VECTOR_CLONES' AVX2 and SSE2
// (pass 1's double-precision positions take 8 lanes instead of 4: ~1.3x the
// samples per second on this EPYC). GCC's avx512f target enables FMA, so
// this file is compiled with -ffp-contract=off (CMakeLists.txt): no
// multiply-add is contracted and every clone gives the same bytes.
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RIS_SAMPLER_CLONES __attribute__((target_clones("avx512f", "avx2", "default")))
#else
#define RIS_SAMPLER_CLONES
#endif

RIS_SAMPLER_CLONES void sample_span_i32(const float* __restrict tex, int rows, int cols,
                                        GridLine line, int begin, int end, float* __restrict height,
                                        float* __restrict dz_dx, float* __restrict dz_dy,
                                        std::uint16_t* __restrict category,
                                        std::uint8_t* __restrict flags) {
  sample_span<std::int32_t>(tex, rows, cols, line, begin, end, height, dz_dx, dz_dy, category,
                            flags);
}

}  // namespace

void sample_terrain_line(const TerrainTexels& tex, const GridLine& line, int begin, int end,
                         const SampledTerrain& out) {
  static_assert(sizeof(TerrainTexel) == 4 * sizeof(float));
  const auto* t = reinterpret_cast<const float*>(tex.texel.get());
  // 32-bit float indices (4 per cell) where they fit: every scene that
  // fits in memory with its texels up to 2^29 cells.
  if (tex.size() < (std::size_t{1} << 29)) {
    sample_span_i32(t, tex.rows, tex.cols, line, begin, end, out.height_m, out.dz_dx, out.dz_dy,
                    out.category, out.flags);
  } else {
    sample_span<std::int64_t>(t, tex.rows, tex.cols, line, begin, end, out.height_m, out.dz_dx,
                              out.dz_dy, out.category, out.flags);
  }
}

}  // namespace ris
