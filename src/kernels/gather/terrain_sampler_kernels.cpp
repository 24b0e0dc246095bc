// The line sampler's kernels (kernels/gather/terrain_sampler_kernels.h),
// moved from geometry/terrain_line.cpp unchanged.
#include "kernels/gather/terrain_sampler_kernels.h"

#include <algorithm>
#include <cstring>
#include <limits>

#include "kernels/simd/avx512.h"
#include "ris/geometry/surface_gradient.h"
#include "ris/geometry/terrain_sample.h"
#include "ris/kernels/vector_clones.h"

namespace ris::kernels {

namespace {

// Hot loops: an AVX2 clone beside the SSE2 default, the same bytes on any
// CPU (ris/kernels/vector_clones.h).

// One row's texels: the interior columns [c_begin, c_end) (within [1, cols -
// 1)) in one pass of selects (slope_difference, no branches) that
// vectorises; the edge columns by cell_slope, the same rule with the bounds
// checked. zs, vs / zn, vn: the rows south (r + 1) and north (r - 1), or a
// row without data beyond the scene's edge.
[[gnu::always_inline]] inline void texel_cells(
    int c_begin, int c_end, double dx_m, double dy_m, const float* __restrict z,
    const std::uint8_t* __restrict v, const std::uint16_t* __restrict cat,
    const float* __restrict zs, const std::uint8_t* __restrict vs, const float* __restrict zn,
    const std::uint8_t* __restrict vn, TerrainTexel* __restrict out) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (int c = c_begin; c < c_end; ++c) {
    const bool ok = v[c] != 0;
    const float gx = slope_difference(v[c - 1] != 0, z[c - 1], v[c + 1] != 0, z[c + 1], z[c], dx_m);
    const float gy = slope_difference(vs[c] != 0, zs[c], vn[c] != 0, zn[c], z[c], dy_m);
    out[c].height_m = ok ? z[c] : nan;
    out[c].dz_dx = ok ? gx : nan;
    out[c].dz_dy = ok ? gy : nan;
    out[c].category = static_cast<float>(cat[c]);
  }
}

RIS_VECTOR_CLONES void texel_row_interior(
    int cols, double dx_m, double dy_m, const float* __restrict z, const std::uint8_t* __restrict v,
    const std::uint16_t* __restrict cat, const float* __restrict zs,
    const std::uint8_t* __restrict vs, const float* __restrict zn,
    const std::uint8_t* __restrict vn, TerrainTexel* __restrict out) {
  texel_cells(1, cols - 1, dx_m, dy_m, z, v, cat, zs, vs, zn, vn, out);
}

#ifdef RIS_HAVE_AVX512_KERNELS
// GCC 12's plain AVX-512 intrinsics pass an undefined register as the
// unused merge source, which -Wmaybe-uninitialized reports once inlined
// (a false positive: every lane is written).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

// Eight cells' valid flags as mask bits.
RIS_AVX512_KERNEL inline __mmask8 valid8(const std::uint8_t* v) {
  const __m128i b = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(v));
  return static_cast<__mmask8>(_mm_test_epi8_mask(b, b));
}

// Eight heights in double.
RIS_AVX512_KERNEL inline __m512d height8(const float* z) {
  return _mm512_cvtps_pd(_mm256_loadu_ps(z));
}

// slope_difference for eight cells, its operations lane by lane.
RIS_AVX512_KERNEL inline __m256 slope8(__mmask8 lo_ok, __m512d z_lo, __mmask8 hi_ok, __m512d z_hi,
                                       __m512d z_c, __m512d step, __m512d two_steps) {
  const __m512d a = _mm512_mask_blend_pd(hi_ok, z_c, z_hi);
  const __m512d b = _mm512_mask_blend_pd(lo_ok, z_c, z_lo);
  const __m512d num = _mm512_maskz_sub_pd(static_cast<__mmask8>(lo_ok | hi_ok), a, b);
  const __m512d den = _mm512_mask_blend_pd(static_cast<__mmask8>(lo_ok & hi_ok), step, two_steps);
  return _mm512_cvtpd_ps(_mm512_div_pd(num, den));
}

// texel_cells eight cells at a time from column 1 (GCC's vectorisation of it
// runs out of registers and spills): slopes in eight double lanes, then the
// four fields interleaved into texels by a 4 x 4 transpose of each half.
// Returns the first column not done.
RIS_AVX512_KERNEL int texel_row_avx512(
    int cols, double dx_m, double dy_m, const float* __restrict z, const std::uint8_t* __restrict v,
    const std::uint16_t* __restrict cat, const float* __restrict zs,
    const std::uint8_t* __restrict vs, const float* __restrict zn,
    const std::uint8_t* __restrict vn, TerrainTexel* __restrict out) {
  const __m512d sx = _mm512_set1_pd(dx_m), sx2 = _mm512_set1_pd(2.0 * dx_m);
  const __m512d sy = _mm512_set1_pd(dy_m), sy2 = _mm512_set1_pd(2.0 * dy_m);
  const __m256 nan = _mm256_set1_ps(std::numeric_limits<float>::quiet_NaN());
  int c = 1;
  for (; c + 8 <= cols - 1; c += 8) {
    const __m512d zc = height8(z + c);
    const __mmask8 ok = valid8(v + c);
    const __m256 gx = slope8(valid8(v + c - 1), height8(z + c - 1), valid8(v + c + 1),
                             height8(z + c + 1), zc, sx, sx2);
    const __m256 gy =
        slope8(valid8(vs + c), height8(zs + c), valid8(vn + c), height8(zn + c), zc, sy, sy2);
    const __m256 h = _mm256_mask_blend_ps(ok, nan, _mm256_loadu_ps(z + c));
    const __m256 hx = _mm256_mask_blend_ps(ok, nan, gx);
    const __m256 hy = _mm256_mask_blend_ps(ok, nan, gy);
    const __m256 k = _mm256_cvtepi32_ps(
        _mm256_cvtepu16_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(cat + c))));
    // Lanes (i, i + 4) of t* hold cells i and i + 4 of the eight.
    const __m256d t0 = _mm256_castps_pd(_mm256_unpacklo_ps(h, hx));
    const __m256d t1 = _mm256_castps_pd(_mm256_unpackhi_ps(h, hx));
    const __m256d t2 = _mm256_castps_pd(_mm256_unpacklo_ps(hy, k));
    const __m256d t3 = _mm256_castps_pd(_mm256_unpackhi_ps(hy, k));
    const __m256 u0 = _mm256_castpd_ps(_mm256_unpacklo_pd(t0, t2));  // cells 0 | 4
    const __m256 u1 = _mm256_castpd_ps(_mm256_unpackhi_pd(t0, t2));  // 1 | 5
    const __m256 u2 = _mm256_castpd_ps(_mm256_unpacklo_pd(t1, t3));  // 2 | 6
    const __m256 u3 = _mm256_castpd_ps(_mm256_unpackhi_pd(t1, t3));  // 3 | 7
    float* const o = &out[c].height_m;
    _mm256_storeu_ps(o, _mm256_permute2f128_ps(u0, u1, 0x20));
    _mm256_storeu_ps(o + 8, _mm256_permute2f128_ps(u2, u3, 0x20));
    _mm256_storeu_ps(o + 16, _mm256_permute2f128_ps(u0, u1, 0x31));
    _mm256_storeu_ps(o + 24, _mm256_permute2f128_ps(u2, u3, 0x31));
  }
  return c;
}
#pragma GCC diagnostic pop
#endif

}  // namespace

// One row's interior texels, by the AVX-512 kernel when `wide` (the CPU has
// it and the caller allows it; then its last columns by texel_cells), else
// by the clones.
void texel_row(bool wide, int cols, double dx_m, double dy_m, const float* z, const std::uint8_t* v,
               const std::uint16_t* cat, const float* zs, const std::uint8_t* vs, const float* zn,
               const std::uint8_t* vn, TerrainTexel* out) {
#ifdef RIS_HAVE_AVX512_KERNELS
  if (wide) {
    const int done = texel_row_avx512(cols, dx_m, dy_m, z, v, cat, zs, vs, zn, vn, out);
    texel_cells(done, cols - 1, dx_m, dy_m, z, v, cat, zs, vs, zn, vn, out);
    return;
  }
#else
  (void)wide;
#endif
  texel_row_interior(cols, dx_m, dy_m, z, v, cat, zs, vs, zn, vn, out);
}

namespace {

// Samples [begin, end) of the line into out[j - begin], a chunk of kChunk
// samples at a time in two passes:
//  1. where (chunk_cells): bilinear_cells over the chunk (selects only, so
//     GCC vectorises it), keeping each sample's first corner, nearest cell
//     and weights;
//  2. what (weigh_texels): per sample, its four corner texels as 4-float
//     vectors (height, dz/dx, dz/dy, category: one 16-byte load each, no
//     gathers) weighted by the broadcast weight, the same float operations
//     in the same corner order as bilinear_terrain_sample lane by lane.
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

// Pass 1's output for one chunk: texel k of a sample's first corner is
// tex[first + k], its nearest cell's category tex[nearest].
template <typename Index>
struct ChunkCells {
  alignas(64) Index first[kChunk];
  alignas(64) Index nearest[kChunk];
  alignas(64) float w0[kChunk];
  alignas(64) float w1[kChunk];
  alignas(64) float w2[kChunk];
  alignas(64) float w3[kChunk];
};

// Pass 1 for chunk samples [k_begin, k_end), sample j0 + k of the line.
template <typename Index>
[[gnu::always_inline]] inline void chunk_cells(int rows, int cols, const GridLine& line, int j0,
                                               int k_begin, int k_end, ChunkCells<Index>& c) {
  for (int k = k_begin; k < k_end; ++k) {
    const BilinearCells<Index> b =
        bilinear_cells<Index>(rows, cols, line.col(j0 + k), line.row(j0 + k));
    c.first[k] = 4 * b.cell00;
    c.nearest[k] = 4 * b.nearest + 3;
    c.w0[k] = b.weight[0];
    c.w1[k] = b.weight[1];
    c.w2[k] = b.weight[2];
    c.w3[k] = b.weight[3];
  }
}

// The corners' offsets (in floats) from the first corner, the same for every
// sample (bilinear_cells' steps): to (r0, c1), (r1, c0), (r1, c1).
template <typename Index>
struct CornerSteps {
  Index d1, d2, d3;
};

template <typename Index>
CornerSteps<Index> corner_steps(int rows, int cols) {
  const BilinearCells<Index> steps = bilinear_cells<Index>(rows, cols, 0.5, 0.5);
  const Index d1 = 4 * steps.step_col, d2 = 4 * steps.step_row;
  return {d1, d2, d2 + d1};
}

// Pass 2 for chunk samples [k_begin, k_end), sample k into out[o0 + k].
template <typename Index>
[[gnu::always_inline]] inline void weigh_texels(const float* __restrict tex,
                                                const ChunkCells<Index>& c, CornerSteps<Index> d,
                                                int k_begin, int k_end, int o0,
                                                const SampledTerrain& out) {
  float* __restrict height = out.height_m;
  float* __restrict dz_dx = out.dz_dx;
  float* __restrict dz_dy = out.dz_dy;
  std::uint16_t* __restrict category = out.category;
  std::uint8_t* __restrict flags = out.flags;
  for (int k = k_begin; k < k_end; ++k) {
    const float* const t = tex + c.first[k];
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
    add(c.w0[k], t);
    add(c.w1[k], t + d.d1);
    add(c.w2[k], t + d.d2);
    add(c.w3[k], t + d.d3);
    const float h = acc[0];
    const bool no_data = h != h;  // NaN
    const int o = o0 + k;
    height[o] = h;
    dz_dx[o] = acc[1];
    dz_dy[o] = acc[2];
    category[o] = no_data ? std::uint16_t{0}
                          : static_cast<std::uint16_t>(static_cast<int>(tex[c.nearest[k]]));
    flags[o] = no_data ? sample_flag::kNoData : std::uint8_t{0};
  }
}

template <typename Index>
[[gnu::always_inline]] inline void sample_span_of(const float* __restrict tex, int rows, int cols,
                                                  const GridLine& line, int begin, int end,
                                                  const SampledTerrain& out) {
  const CornerSteps<Index> d = corner_steps<Index>(rows, cols);
  ChunkCells<Index> c;
  for (int j0 = begin; j0 < end; j0 += kChunk) {
    const int n = std::min(kChunk, end - j0);
    chunk_cells(rows, cols, line, j0, 0, n, c);
    weigh_texels(tex, c, d, 0, n, j0 - begin, out);
  }
}

// The sampler's portable clones: AVX2 beside SSE2 (ris/kernels/vector_clones.h;
// on a CPU with AVX-512, sample_span_avx512 runs instead).
RIS_VECTOR_CLONES void sample_span_i32(const float* __restrict tex, int rows, int cols,
                                       const GridLine& line, int begin, int end,
                                       const SampledTerrain& out) {
  sample_span_of<std::int32_t>(tex, rows, cols, line, begin, end, out);
}

#ifdef RIS_HAVE_AVX512_KERNELS
// GCC 12's plain AVX-512 intrinsics pass an undefined register as the
// unused merge source, which -Wmaybe-uninitialized reports once inlined
// (a false positive: every lane is written).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

// One axis of bilinear_cells for eight samples (its operations lane by lane,
// so the same bits): the lower cell index, the weight fraction and whether
// the point lies in the upper cell. a0, da: the line's start and step on
// this axis; j: the samples' indices; hi: the outermost centre (n - 1);
// cell_max: the largest lower cell (n - 2, or 0).
struct AxisCells8 {
  __m256i cell;
  __m256 fraction;
  __mmask8 upper;
};

RIS_AVX512_KERNEL inline AxisCells8 axis_cells8(__m512d a0, __m512d da, __m512d j, __m512d hi,
                                                __m256i cell_max) {
  const __m512d zero = _mm512_setzero_pd(), half = _mm512_set1_pd(0.5);
  const __m512d a = _mm512_add_pd(a0, _mm512_mul_pd(j, da));  // GridLine::col / row
  // clamp(a - 1/2, 0, hi): maxpd / minpd return their second operand on a
  // tie, so the value itself as bilinear_cells' selects keep it.
  const __m512d p = _mm512_min_pd(hi, _mm512_max_pd(zero, _mm512_sub_pd(a, half)));
  const __m256i cell = _mm256_min_epi32(_mm512_cvttpd_epi32(p), cell_max);
  const __m512d f = _mm512_sub_pd(p, _mm512_cvtepi32_pd(cell));
  return {cell, _mm512_cvtpd_ps(f), _mm512_cmp_pd_mask(f, half, _CMP_GE_OQ)};
}

// Pass 1 (chunk_cells) eight samples at a time: GCC's own vectorisation of
// it mixes eight-lane doubles with sixteen-lane indices and spends a third
// of its instructions moving masks and halves. Returns the samples done (a
// multiple of 8).
RIS_AVX512_KERNEL int chunk_cells_avx512(int rows, int cols, const GridLine& line, int j0, int n,
                                         ChunkCells<std::int32_t>& c) {
  const BilinearCells<std::int32_t> steps = bilinear_cells<std::int32_t>(rows, cols, 0.5, 0.5);
  const __m512d col0 = _mm512_set1_pd(line.col0), dcol = _mm512_set1_pd(line.dcol);
  const __m512d row0 = _mm512_set1_pd(line.row0), drow = _mm512_set1_pd(line.drow);
  const __m512d col_hi = _mm512_set1_pd(double(cols - 1)),
                row_hi = _mm512_set1_pd(double(rows - 1));
  const __m256i col_max = _mm256_set1_epi32(cols > 2 ? cols - 2 : 0);
  const __m256i row_max = _mm256_set1_epi32(rows > 2 ? rows - 2 : 0);
  const __m256i n_cols = _mm256_set1_epi32(cols);
  const __m256i step_col = _mm256_set1_epi32(steps.step_col);
  const __m256i step_row = _mm256_set1_epi32(steps.step_row);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  const __m256 one = _mm256_set1_ps(1.0f);
  int k = 0;
  for (; k + 8 <= n; k += 8) {
    const __m512d j = _mm512_cvtepi32_pd(_mm256_add_epi32(_mm256_set1_epi32(j0 + k), lane));
    const AxisCells8 x = axis_cells8(col0, dcol, j, col_hi, col_max);
    const AxisCells8 y = axis_cells8(row0, drow, j, row_hi, row_max);
    const __m256i cell00 = _mm256_add_epi32(_mm256_mullo_epi32(y.cell, n_cols), x.cell);
    __m256i nearest = _mm256_mask_add_epi32(cell00, x.upper, cell00, step_col);
    nearest = _mm256_mask_add_epi32(nearest, y.upper, nearest, step_row);
    _mm256_store_si256(reinterpret_cast<__m256i*>(c.first + k), _mm256_slli_epi32(cell00, 2));
    _mm256_store_si256(reinterpret_cast<__m256i*>(c.nearest + k),
                       _mm256_add_epi32(_mm256_slli_epi32(nearest, 2), _mm256_set1_epi32(3)));
    const __m256 ox = _mm256_sub_ps(one, x.fraction), oy = _mm256_sub_ps(one, y.fraction);
    _mm256_store_ps(c.w0 + k, _mm256_mul_ps(ox, oy));
    _mm256_store_ps(c.w1 + k, _mm256_mul_ps(x.fraction, oy));
    _mm256_store_ps(c.w2 + k, _mm256_mul_ps(ox, y.fraction));
    _mm256_store_ps(c.w3 + k, _mm256_mul_ps(x.fraction, y.fraction));
  }
  return k;
}

// Pass 2 sixteen samples at a time with AVX-512 (weigh_texels' operations
// lane by lane, so the same bytes): each 512-bit register holds four
// samples' texels (one 128-bit lane each) and their weights broadcast per
// lane; a weight above 0 masks the add (acc + 0 where the scalar pass
// selects 0: acc is never -0, as it starts at +0 and a sum that is zero
// rounds to +0, so both leave acc as it was). Four registers of sums are
// then transposed into height, dz/dx and dz/dy; the nearest cell's category
// is one masked gather (none where the sample has no data). Against the
// 128-bit pass (a broadcast, a multiply, a compare, an and and an add per
// corner and sample, then three lane extracts): about a third of the
// instructions. Returns the samples done (a multiple of 16).
RIS_AVX512_KERNEL int weigh_texels_avx512(const float* __restrict tex,
                                          const ChunkCells<std::int32_t>& c,
                                          CornerSteps<std::int32_t> d, int n, int o0,
                                          const SampledTerrain& out) {
  // Four samples' weights, each broadcast over its 128-bit lane.
  const __m512i quad[4] = {
      _mm512_setr_epi32(0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3),
      _mm512_setr_epi32(4, 4, 4, 4, 5, 5, 5, 5, 6, 6, 6, 6, 7, 7, 7, 7),
      _mm512_setr_epi32(8, 8, 8, 8, 9, 9, 9, 9, 10, 10, 10, 10, 11, 11, 11, 11),
      _mm512_setr_epi32(12, 12, 12, 12, 13, 13, 13, 13, 14, 14, 14, 14, 15, 15, 15, 15)};
  // Transpose: sums of samples 0-3 (a) and 4-7 (b) -> their heights, then
  // their dz/dx; -> their dz/dy (upper half unused); two such halves ->
  // sixteen samples' values.
  const __m512i h_gx = _mm512_setr_epi32(0, 4, 8, 12, 16, 20, 24, 28, 1, 5, 9, 13, 17, 21, 25, 29);
  const __m512i gy = _mm512_setr_epi32(2, 6, 10, 14, 18, 22, 26, 30, 2, 6, 10, 14, 18, 22, 26, 30);
  const __m512i low_halves =
      _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 16, 17, 18, 19, 20, 21, 22, 23);
  const __m512i high_halves =
      _mm512_setr_epi32(8, 9, 10, 11, 12, 13, 14, 15, 24, 25, 26, 27, 28, 29, 30, 31);
  const __m512 zero = _mm512_setzero_ps();
  // Local copies: a store through one output would otherwise make GCC
  // reload the others from `out`.
  float* __restrict height = out.height_m;
  float* __restrict dz_dx = out.dz_dx;
  float* __restrict dz_dy = out.dz_dy;
  std::uint16_t* __restrict category = out.category;
  std::uint8_t* __restrict flags = out.flags;
  int k = 0;
  for (; k + 16 <= n; k += 16) {
    const __m512 w16[4] = {_mm512_load_ps(c.w0 + k), _mm512_load_ps(c.w1 + k),
                           _mm512_load_ps(c.w2 + k), _mm512_load_ps(c.w3 + k)};
    __m512 acc[4];
    // Group by group of four samples (four corner pointers live at a time).
#pragma GCC unroll 4
    for (int g = 0; g < 4; ++g) {
      const float* const p[4] = {tex + c.first[k + 4 * g], tex + c.first[k + 4 * g + 1],
                                 tex + c.first[k + 4 * g + 2], tex + c.first[k + 4 * g + 3]};
      const std::int32_t offset[4] = {0, d.d1, d.d2, d.d3};
      __m512 a = zero;
#pragma GCC unroll 4
      for (int corner = 0; corner < 4; ++corner) {
        const std::int32_t off = offset[corner];
        __m512 t = _mm512_castps128_ps512(_mm_loadu_ps(p[0] + off));
        t = _mm512_insertf32x4(t, _mm_loadu_ps(p[1] + off), 1);
        t = _mm512_insertf32x4(t, _mm_loadu_ps(p[2] + off), 2);
        t = _mm512_insertf32x4(t, _mm_loadu_ps(p[3] + off), 3);
        const __m512 w = _mm512_permutexvar_ps(quad[g], w16[corner]);
        const __mmask16 keep = _mm512_cmp_ps_mask(w, zero, _CMP_GT_OQ);
        a = _mm512_mask_add_ps(a, keep, a, _mm512_mul_ps(w, t));
      }
      acc[g] = a;
    }
    const __m512 hg01 = _mm512_permutex2var_ps(acc[0], h_gx, acc[1]);
    const __m512 hg23 = _mm512_permutex2var_ps(acc[2], h_gx, acc[3]);
    const __m512 y01 = _mm512_permutex2var_ps(acc[0], gy, acc[1]);
    const __m512 y23 = _mm512_permutex2var_ps(acc[2], gy, acc[3]);
    const __m512 h = _mm512_permutex2var_ps(hg01, low_halves, hg23);
    const int o = o0 + k;
    _mm512_storeu_ps(height + o, h);
    _mm512_storeu_ps(dz_dx + o, _mm512_permutex2var_ps(hg01, high_halves, hg23));
    _mm512_storeu_ps(dz_dy + o, _mm512_permutex2var_ps(y01, low_halves, y23));
    const __mmask16 no_data = _mm512_cmp_ps_mask(h, h, _CMP_UNORD_Q);
    // The nearest cells' categories by scalar loads (an AVX-512 gather is
    // slower on this EPYC), zero where no data.
    alignas(64) float nearest_category[16];
    for (int i = 0; i < 16; ++i) nearest_category[i] = tex[c.nearest[k + i]];
    const __m512i cat = _mm512_maskz_cvttps_epi32(static_cast<__mmask16>(~no_data),
                                                  _mm512_load_ps(nearest_category));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(category + o), _mm512_cvtepi32_epi16(cat));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(flags + o),
                     _mm512_cvtepi32_epi8(_mm512_maskz_set1_epi32(no_data, sample_flag::kNoData)));
  }
  return k;
}

// The sampler with pass 2 in AVX-512 (pass 1 vectorised by GCC for it:
// eight double positions a register), the last samples of each chunk by
// the scalar pass.
RIS_AVX512_KERNEL void sample_span_avx512(const float* __restrict tex, int rows, int cols,
                                          const GridLine& line, int begin, int end,
                                          const SampledTerrain& out) {
  const CornerSteps<std::int32_t> d = corner_steps<std::int32_t>(rows, cols);
  ChunkCells<std::int32_t> c;
  for (int j0 = begin; j0 < end; j0 += kChunk) {
    const int n = std::min(kChunk, end - j0);
    const int cells_done = chunk_cells_avx512(rows, cols, line, j0, n, c);
    chunk_cells(rows, cols, line, j0, cells_done, n, c);
    const int done = weigh_texels_avx512(tex, c, d, n, j0 - begin, out);
    weigh_texels(tex, c, d, done, n, j0 - begin, out);
  }
}
#pragma GCC diagnostic pop
#endif

}  // namespace

void sample_span(bool wide, const float* tex, int rows, int cols, const GridLine& line, int begin,
                 int end, const SampledTerrain& out) {
  // 32-bit float indices (4 per cell) where they fit: every scene that
  // fits in memory with its texels up to 2^29 cells.
  if (std::size_t(rows) * std::size_t(cols) < (std::size_t{1} << 29)) {
#ifdef RIS_HAVE_AVX512_KERNELS
    if (wide) {
      sample_span_avx512(tex, rows, cols, line, begin, end, out);
      return;
    }
#else
    (void)wide;
#endif
    sample_span_i32(tex, rows, cols, line, begin, end, out);
  } else {
    sample_span_of<std::int64_t>(tex, rows, cols, line, begin, end, out);
  }
}

}  // namespace ris::kernels
