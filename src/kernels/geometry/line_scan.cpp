#include "ris/geometry/line_scan.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "kernels/simd/vec8.h"
#include "ris/kernels/vector_clones.h"
#include "ris/util/fast_math.h"

// GCC 12's AVX-512 intrinsics pass _mm512_undefined_*() as the masked-off
// source of the unmasked forms, which -Wmaybe-uninitialized reports once they
// are inlined (GCC bug 105593, fixed in GCC 13): a false positive. (Before
// the intrinsics' headers, whose lines the warning points at.)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "kernels/simd/avx512.h"
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace ris {

namespace {
constexpr std::uint8_t kSkip = sample_flag::kNoData | sample_flag::kUnseen;
}

namespace {

// look_line's loops, with restrict-qualified parameters: the arrays never
// alias, which lets them vectorise without run-time overlap checks. They
// have an AVX-512 clone (this file is compiled with -ffp-contract=off): the
// fused along-axis benchmark ~4% faster on this EPYC (the other loops here
// gained nothing measurable from it). With
// kIncidence the same loop also gives the look angle from nadir atan2(u, D)
// = atan(u / D) (D > 0: terrain below the sensor is checked before), which
// reuses its loads and D rather than a pass of its own.
template <bool kIncidence>
__attribute__((always_inline)) inline void look_loop(
    int n, float H, float lx, float ly, float element, const float* __restrict u_m,
    const float* __restrict height, const float* __restrict gx, const float* __restrict gy,
    float* __restrict range, float* __restrict local, float* __restrict area,
    float* __restrict dh_du, float* __restrict inc) {
  for (int j = 0; j < n; ++j) {
    const float u = u_m[j];
    const float D = H - height[j];
    const float R = std::sqrt(u * u + D * D);
    // Slope along the look direction and the facet normal's length
    // |(-dz/dx, -dz/dy, 1)| (MODEL.md section 2-3; as look_at).
    const float dh = gx[j] * lx + gy[j] * ly;
    const float n_len = std::sqrt(1.0f + gx[j] * gx[j] + gy[j] * gy[j]);
    // theta_l = atan2(|n x l|, n . l) with n = (-dz/dx, -dz/dy, 1) and l =
    // (-u look, D) / R towards the sensor: unlike acos(n . l) in single
    // precision, accurate to ~1e-7 rad also near theta_l = 0. n . l R =
    // u dh + D, whose sign is that of cos(theta_l).
    const float dot = u * dh + D;
    const float cx = u * ly - gy[j] * D;
    const float cy = gx[j] * D - u * lx;
    const float cz = u * (gx[j] * ly - gy[j] * lx);
    const float cross = std::sqrt(cx * cx + cy * cy + cz * cz);
    const float a = fast_atan(cross / std::fabs(dot));
    range[j] = R;
    local[j] = dot < 0.0f ? kPiF - a : a;
    area[j] = element * n_len;
    dh_du[j] = dh;
    if constexpr (kIncidence) inc[j] = fast_atan(u / D);
  }
}

RIS_WIDE_VECTOR_CLONES void look_kernel(int n, float H, float lx, float ly, float element,
                                        const float* __restrict u_m, const float* __restrict height,
                                        const float* __restrict gx, const float* __restrict gy,
                                        float* __restrict range, float* __restrict local,
                                        float* __restrict area, float* __restrict dh_du) {
  look_loop<false>(n, H, lx, ly, element, u_m, height, gx, gy, range, local, area, dh_du, nullptr);
}

RIS_WIDE_VECTOR_CLONES void look_incidence_kernel(
    int n, float H, float lx, float ly, float element, const float* __restrict u_m,
    const float* __restrict height, const float* __restrict gx, const float* __restrict gy,
    float* __restrict range, float* __restrict local, float* __restrict area,
    float* __restrict dh_du, float* __restrict inc) {
  look_loop<true>(n, H, lx, ly, element, u_m, height, gx, gy, range, local, area, dh_du, inc);
}

// Back-facing where n . l <= 0 (look_loop's expression, so the same float).
RIS_VECTOR_CLONES void back_facing_kernel(int n, float H, const float* __restrict u_m,
                                          const float* __restrict height,
                                          const float* __restrict dh_du,
                                          std::uint8_t* __restrict flags) {
  for (int j = 0; j < n; ++j) {
    const float dot = u_m[j] * dh_du[j] + (H - height[j]);
    flags[j] = static_cast<std::uint8_t>(flags[j] | (dot <= 0.0f ? sample_flag::kBackFacing : 0));
  }
}

}  // namespace

void look_line(const LineTerrain& in, const LineLookFrame& fr, const LineLook& out) {
  const float H = static_cast<float>(fr.altitude_m);
  const float lx = static_cast<float>(fr.look_x), ly = static_cast<float>(fr.look_y);
  const float element = static_cast<float>(fr.element_m2);
  if (out.incidence_rad) {
    look_incidence_kernel(in.samples, H, lx, ly, element, in.u_m, in.height_m, in.dz_dx, in.dz_dy,
                          out.slant_range_m, out.local_incidence_rad, out.area_m2, out.dh_du,
                          out.incidence_rad);
  } else {
    look_kernel(in.samples, H, lx, ly, element, in.u_m, in.height_m, in.dz_dx, in.dz_dy,
                out.slant_range_m, out.local_incidence_rad, out.area_m2, out.dh_du);
  }
  back_facing_kernel(in.samples, H, in.u_m, in.height_m, out.dh_du, out.flags);
}

namespace {

// The slant range of element j's two ends (line_element_ends) given whether
// it and its neighbours have data; NaN when it has none.
inline void element_ends_at(int j, bool has, bool has_lo, bool has_hi, float u, float h_lo, float h,
                            float h_hi, float dh_du, float H, float half_step,
                            float* __restrict near_end, float* __restrict far_end) {
  const float slope_half = dh_du * half_step;
  const float h_near = has_lo ? 0.5f * (h + h_lo) : h - slope_half;
  const float h_far = has_hi ? 0.5f * (h + h_hi) : h + slope_half;
  const float un = u - half_step, uf = u + half_step;
  const float dn = H - h_near, df = H - h_far;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  near_end[j] = has ? std::sqrt(un * un + dn * dn) : nan;
  far_end[j] = has ? std::sqrt(uf * uf + df * df) : nan;
}

// Samples [j0, j1) with 1 <= j0 and j1 <= n - 1, whose two neighbours
// exist: no branches, so that it vectorises.
RIS_VECTOR_CLONES void element_ends_interior(int j0, int j1, double first_u, double step, float H,
                                             float half_step, const float* __restrict h,
                                             const float* __restrict dh_du,
                                             const std::uint8_t* __restrict flags,
                                             float* __restrict near_end,
                                             float* __restrict far_end) {
  for (int j = j0; j < j1; ++j) {
    element_ends_at(j, !(flags[j] & kSkip), !(flags[j - 1] & kSkip), !(flags[j + 1] & kSkip),
                    static_cast<float>(first_u + j * step), h[j - 1], h[j], h[j + 1], dh_du[j], H,
                    half_step, near_end, far_end);
  }
}

#ifdef RIS_HAVE_AVX512_KERNELS
// Which of sixteen samples from flags are taken (not kNoData, kUnseen).
RIS_AVX512_KERNEL inline __mmask16 taken16(const std::uint8_t* flags, __m128i skip) {
  return _mm_testn_epi8_mask(_mm_loadu_si128(reinterpret_cast<const __m128i*>(flags)), skip);
}

// element_ends_interior sixteen samples at a time with AVX-512 (element_ends_at's
// operations lane by lane, u in double as the scalar rule, the neighbours'
// flags as mask registers); returns the first sample not done.
RIS_AVX512_KERNEL int element_ends_avx512(int j0, int j1, double first_u, double step, float H,
                                          float half_step, const float* __restrict h,
                                          const float* __restrict dh_du,
                                          const std::uint8_t* __restrict flags,
                                          float* __restrict near_end, float* __restrict far_end) {
  const __m128i skip = _mm_set1_epi8(static_cast<char>(kSkip));
  const __m512 H_v = _mm512_set1_ps(H), half_v = _mm512_set1_ps(half_step),
               mid = _mm512_set1_ps(0.5f),
               nan = _mm512_set1_ps(std::numeric_limits<float>::quiet_NaN());
  const __m512d first_v = _mm512_set1_pd(first_u), step_v = _mm512_set1_pd(step),
                sixteen = _mm512_set1_pd(16.0);
  // j as exact doubles, as the scalar rule's int-to-double conversion.
  __m512d j_lo = _mm512_add_pd(_mm512_set1_pd(j0), _mm512_set_pd(7, 6, 5, 4, 3, 2, 1, 0));
  __m512d j_hi = _mm512_add_pd(j_lo, _mm512_set1_pd(8.0));
  int j = j0;
  for (; j + 16 <= j1; j += 16) {
    const auto jj = static_cast<std::size_t>(j);
    const __mmask16 has = taken16(flags + jj, skip), has_lo = taken16(flags + jj - 1, skip),
                    has_hi = taken16(flags + jj + 1, skip);
    const __m512 hv = _mm512_loadu_ps(h + jj);
    const __m512 slope_half = _mm512_mul_ps(_mm512_loadu_ps(dh_du + jj), half_v);
    const __m512 h_near =
        _mm512_mask_blend_ps(has_lo, _mm512_sub_ps(hv, slope_half),
                             _mm512_mul_ps(mid, _mm512_add_ps(hv, _mm512_loadu_ps(h + jj - 1))));
    const __m512 h_far =
        _mm512_mask_blend_ps(has_hi, _mm512_add_ps(hv, slope_half),
                             _mm512_mul_ps(mid, _mm512_add_ps(hv, _mm512_loadu_ps(h + jj + 1))));
    const __m512 u = _mm512_insertf32x8(
        _mm512_castps256_ps512(
            _mm512_cvtpd_ps(_mm512_add_pd(first_v, _mm512_mul_pd(j_lo, step_v)))),
        _mm512_cvtpd_ps(_mm512_add_pd(first_v, _mm512_mul_pd(j_hi, step_v))), 1);
    j_lo = _mm512_add_pd(j_lo, sixteen);
    j_hi = _mm512_add_pd(j_hi, sixteen);
    const __m512 un = _mm512_sub_ps(u, half_v), uf = _mm512_add_ps(u, half_v);
    const __m512 dn = _mm512_sub_ps(H_v, h_near), df = _mm512_sub_ps(H_v, h_far);
    const __m512 rn = _mm512_sqrt_ps(_mm512_add_ps(_mm512_mul_ps(un, un), _mm512_mul_ps(dn, dn)));
    const __m512 rf = _mm512_sqrt_ps(_mm512_add_ps(_mm512_mul_ps(uf, uf), _mm512_mul_ps(df, df)));
    _mm512_storeu_ps(near_end + jj, _mm512_mask_blend_ps(has, nan, rn));
    _mm512_storeu_ps(far_end + jj, _mm512_mask_blend_ps(has, nan, rf));
  }
  return j;
}
#endif

}  // namespace

void line_element_ends(const LineSamples& l, ScanKernel kernel) {
  const float H = static_cast<float>(l.altitude_m);
  const float half_step = static_cast<float>(0.5 * l.step_m);
  const int n = l.samples;
  if (n <= 0) return;
  const auto has = [&](int j) { return j >= 0 && j < n && !(l.flags[j] & kSkip); };
  const auto h = [&](int j) { return j >= 0 && j < n ? l.height_m[j] : 0.0f; };
  const auto edge = [&](int j) {
    element_ends_at(j, has(j), has(j - 1), has(j + 1),
                    static_cast<float>(l.first_u_m + j * l.step_m), h(j - 1), h(j), h(j + 1),
                    l.dh_du[j], H, half_step, l.range_near_end_m, l.range_far_end_m);
  };
  edge(0);
  if (n == 1) return;
  int j = 1;
#ifdef RIS_HAVE_AVX512_KERNELS
  if (cpu_has_avx512() && kernel == ScanKernel::best) {
    j = element_ends_avx512(1, n - 1, l.first_u_m, l.step_m, H, half_step, l.height_m, l.dh_du,
                            l.flags, l.range_near_end_m, l.range_far_end_m);
  }
#endif
  element_ends_interior(j, n - 1, l.first_u_m, l.step_m, H, half_step, l.height_m, l.dh_du, l.flags,
                        l.range_near_end_m, l.range_far_end_m);
  edge(n - 1);
}

namespace {

// cot psi = (H - h) / u of sample j at u = first_u + j step, +inf where
// skipped.
inline double cot_look_angle_at(int j, double first_u, double step, double H, float h,
                                std::uint8_t flags) {
  const double c = (H - double(h)) / (first_u + j * step);
  return (flags & kSkip) ? std::numeric_limits<double>::infinity() : c;
}

// The same for samples [j0, j0 + n) (branch-free: it vectorises).
RIS_VECTOR_CLONES void cot_look_angle(int j0, int n, double first_u, double step, double H,
                                      const float* __restrict h,
                                      const std::uint8_t* __restrict flags,
                                      double* __restrict cot) {
  for (int k = 0; k < n; ++k) {
    const int j = j0 + k;
    cot[k] = cot_look_angle_at(j, first_u, step, H, h[j], flags[j]);
  }
}

}  // namespace

namespace {

// The scans eight samples at a time (kernels/simd/vec8.h): a running minimum or
// maximum is an inclusive prefix scan, log-step within the block (three
// shifts and mins), then combined with the previous blocks' value, so the
// chain from block to block is one min and one broadcast instead of one
// dependent min per sample. The tests compare each sample with the
// inclusive scan: x > min(m, x) <=> x > m (likewise for max), so no shift to
// the exclusive scan is needed.
using vec8::F8;
using vec8::I8;
using vec8::kLanes;
using D4 = double __attribute__((vector_size(32)));
using L4 = std::int64_t __attribute__((vector_size(32)));
using I4 = std::int32_t __attribute__((vector_size(16)));

inline D4 vmin4(D4 a, D4 b) {
  return b < a ? b : a;  // std::min(a, b)
}

// Inclusive prefix minimum of the lanes (lane k: min of lanes 0..k).
inline D4 prefix_min(D4 x) {
  const D4 inf = D4{} + std::numeric_limits<double>::infinity();
  x = vmin4(x, vec8::shuffle(x, inf, L4{4, 0, 1, 2}));
  return vmin4(x, vec8::shuffle(x, inf, L4{4, 5, 0, 1}));
}
inline F8 prefix_max(F8 x) {
  const F8 lo = vec8::splat(-std::numeric_limits<float>::infinity());
  x = vec8::vmax(x, vec8::shuffle(x, lo, I8{8, 0, 1, 2, 3, 4, 5, 6}));
  x = vec8::vmax(x, vec8::shuffle(x, lo, I8{8, 9, 0, 1, 2, 3, 4, 5}));
  return vec8::vmax(x, vec8::shuffle(x, lo, I8{8, 9, 10, 11, 0, 1, 2, 3}));
}
// Inclusive suffix minimum (lane k: min of lanes k..7).
inline F8 suffix_min(F8 x) {
  const F8 hi = vec8::splat(std::numeric_limits<float>::infinity());
  x = vec8::vmin(x, vec8::shuffle(x, hi, I8{1, 2, 3, 4, 5, 6, 7, 8}));
  x = vec8::vmin(x, vec8::shuffle(x, hi, I8{2, 3, 4, 5, 6, 7, 8, 9}));
  return vec8::vmin(x, vec8::shuffle(x, hi, I8{4, 5, 6, 7, 8, 9, 10, 11}));
}

// Forward: shadow (cot psi above the running minimum of the nearer samples')
// and the near-to-far layover scan over samples [j0, j0 + n), n a multiple of
// 8, cot psi of sample j0 + k in cot[k]; the running values carried in and
// out.
RIS_VECTOR_CLONES void forward_scan(int n, const double* __restrict cot,
                                    const float* __restrict range, std::uint8_t* __restrict flags,
                                    double& cot_min, float& max_r) {
  using namespace vec8;
  const F8 neg_inf = splat(-std::numeric_limits<float>::infinity());
  D4 cot_carry = D4{} + cot_min;
  F8 r_carry = splat(max_r);
  for (int k = 0; k < n; k += kLanes) {
    const auto kk = static_cast<std::size_t>(k);
    const I8 f = widen_u8(load<U8x8>(flags + kk));
    const I8 take = (f & kSkip) == 0;
    const D4 c_lo = load<D4>(cot + kk), c_hi = load<D4>(cot + kk + 4);
    const D4 m_lo = vmin4(prefix_min(c_lo), cot_carry);
    const D4 m_hi = vmin4(prefix_min(c_hi), vec8::shuffle(m_lo, L4{3, 3, 3, 3}));
    cot_carry = vec8::shuffle(m_hi, L4{3, 3, 3, 3});
    // The two halves' comparisons (64-bit lanes) as one 8-lane mask.
    const I8 above =
        __builtin_shufflevector(__builtin_convertvector(c_lo > m_lo, I4),
                                __builtin_convertvector(c_hi > m_hi, I4), 0, 1, 2, 3, 4, 5, 6, 7);
    const F8 r = load<F8>(range + kk);
    const F8 m_r = vmax(prefix_max(take ? r : neg_inf), r_carry);
    r_carry = vec8::shuffle(m_r, I8{7, 7, 7, 7, 7, 7, 7, 7});
    const I8 out =
        f | (take & above & sample_flag::kShadow) | (take & (r < m_r) & sample_flag::kLayover);
    store(flags + kk, narrow_u8(out));
  }
  cot_min = cot_carry[0];
  max_r = r_carry[0];
}

// Backward: the far-to-near layover scan over samples [0, n), n a multiple of
// 8, from the far end; the running minimum carried in.
RIS_VECTOR_CLONES void backward_scan(int n, const float* __restrict range,
                                     std::uint8_t* __restrict flags, float min_r) {
  using namespace vec8;
  const F8 inf = splat(std::numeric_limits<float>::infinity());
  F8 carry = splat(min_r);
  for (int k = n - kLanes; k >= 0; k -= kLanes) {
    const auto kk = static_cast<std::size_t>(k);
    const I8 f = widen_u8(load<U8x8>(flags + kk));
    const I8 take = (f & kSkip) == 0;
    const F8 r = load<F8>(range + kk);
    const F8 m = vmin(suffix_min(take ? r : inf), carry);
    carry = vec8::shuffle(m, I8{0, 0, 0, 0, 0, 0, 0, 0});
    store(flags + kk, narrow_u8(f | (take & (r > m) & sample_flag::kLayover)));
  }
}

#ifdef RIS_HAVE_AVX512_KERNELS

// The scans sixteen samples at a time with AVX-512: the same tests as
// forward_scan and backward_scan (and cot_look_angle's operations: one
// multiply, one add, one subtraction and one division in double), with the
// flags as a 16-bit mask register instead of eight 32-bit lanes, which
// takes about a third of the eight-lane loops' instructions (their
// conversions between bytes, lanes and halves were most of them). The
// prefix scans shift lanes in with valign and the carried value is one
// min / max per block, off the block's own scan.

// Inclusive prefix min / max and suffix min of the lanes.
RIS_AVX512_KERNEL inline __m512d prefix_min8(__m512d x) {
  const __m512i inf = _mm512_castpd_si512(_mm512_set1_pd(std::numeric_limits<double>::infinity()));
  const __m512i xi = _mm512_castpd_si512(x);
  x = _mm512_min_pd(x, _mm512_castsi512_pd(_mm512_alignr_epi64(xi, inf, 7)));
  x = _mm512_min_pd(x, _mm512_castsi512_pd(_mm512_alignr_epi64(_mm512_castpd_si512(x), inf, 6)));
  return _mm512_min_pd(x, _mm512_castsi512_pd(_mm512_alignr_epi64(_mm512_castpd_si512(x), inf, 4)));
}
RIS_AVX512_KERNEL inline __m512 prefix_max16(__m512 x) {
  const __m512i lo = _mm512_castps_si512(_mm512_set1_ps(-std::numeric_limits<float>::infinity()));
  x = _mm512_max_ps(x, _mm512_castsi512_ps(_mm512_alignr_epi32(_mm512_castps_si512(x), lo, 15)));
  x = _mm512_max_ps(x, _mm512_castsi512_ps(_mm512_alignr_epi32(_mm512_castps_si512(x), lo, 14)));
  x = _mm512_max_ps(x, _mm512_castsi512_ps(_mm512_alignr_epi32(_mm512_castps_si512(x), lo, 12)));
  return _mm512_max_ps(x, _mm512_castsi512_ps(_mm512_alignr_epi32(_mm512_castps_si512(x), lo, 8)));
}
RIS_AVX512_KERNEL inline __m512 suffix_min16(__m512 x) {
  const __m512i hi = _mm512_castps_si512(_mm512_set1_ps(std::numeric_limits<float>::infinity()));
  x = _mm512_min_ps(x, _mm512_castsi512_ps(_mm512_alignr_epi32(hi, _mm512_castps_si512(x), 1)));
  x = _mm512_min_ps(x, _mm512_castsi512_ps(_mm512_alignr_epi32(hi, _mm512_castps_si512(x), 2)));
  x = _mm512_min_ps(x, _mm512_castsi512_ps(_mm512_alignr_epi32(hi, _mm512_castps_si512(x), 4)));
  return _mm512_min_ps(x, _mm512_castsi512_ps(_mm512_alignr_epi32(hi, _mm512_castps_si512(x), 8)));
}

// cot psi of eight samples from j (cot_look_angle's rule), +inf where not
// taken.
RIS_AVX512_KERNEL inline __m512d cot8(__m256 h, __m512d j, __m512d first_u, __m512d step, __m512d H,
                                      __mmask8 take) {
  const __m512d c = _mm512_div_pd(_mm512_sub_pd(H, _mm512_cvtps_pd(h)),
                                  _mm512_add_pd(first_u, _mm512_mul_pd(j, step)));
  return _mm512_mask_mov_pd(_mm512_set1_pd(std::numeric_limits<double>::infinity()), take, c);
}

// forward_scan over samples [0, n), n a multiple of 16, cot psi computed
// here.
RIS_AVX512_KERNEL void forward_scan_avx512(int n, double first_u, double step, double H,
                                           const float* __restrict h, const float* __restrict range,
                                           std::uint8_t* __restrict flags, double& cot_min,
                                           float& max_r) {
  const __m512d first_v = _mm512_set1_pd(first_u), step_v = _mm512_set1_pd(step),
                H_v = _mm512_set1_pd(H);
  const __m512i last_d = _mm512_set1_epi64(7), last_f = _mm512_set1_epi32(15);
  const __m512 neg_inf = _mm512_set1_ps(-std::numeric_limits<float>::infinity());
  const __m128i skip = _mm_set1_epi8(static_cast<char>(kSkip));
  const __m128i shadow_bit = _mm_set1_epi8(static_cast<char>(sample_flag::kShadow));
  const __m128i layover_bit = _mm_set1_epi8(static_cast<char>(sample_flag::kLayover));
  __m512d carry = _mm512_set1_pd(cot_min);
  __m512 r_carry = _mm512_set1_ps(max_r);
  __m512d j = _mm512_set_pd(7, 6, 5, 4, 3, 2, 1, 0);
  const __m512d eight = _mm512_set1_pd(8.0);
  for (int k = 0; k < n; k += 16) {
    const auto kk = static_cast<std::size_t>(k);
    const __m128i f = _mm_loadu_si128(reinterpret_cast<const __m128i*>(flags + kk));
    const __mmask16 take = _mm_testn_epi8_mask(f, skip);
    // j holds exact integers (as the scalar rule's int-to-double j).
    const __m512d c0 =
        cot8(_mm256_loadu_ps(h + kk), j, first_v, step_v, H_v, static_cast<__mmask8>(take));
    j = _mm512_add_pd(j, eight);
    const __m512d c1 = cot8(_mm256_loadu_ps(h + kk + 8), j, first_v, step_v, H_v,
                            static_cast<__mmask8>(take >> 8));
    j = _mm512_add_pd(j, eight);
    const __m512d p0 = prefix_min8(c0);
    const __m512d p1 = _mm512_min_pd(prefix_min8(c1), _mm512_permutexvar_pd(last_d, p0));
    const __mmask16 above =
        static_cast<__mmask16>(_mm512_cmp_pd_mask(c0, _mm512_min_pd(p0, carry), _CMP_GT_OQ) |
                               (_mm512_cmp_pd_mask(c1, _mm512_min_pd(p1, carry), _CMP_GT_OQ) << 8));
    carry = _mm512_min_pd(carry, _mm512_permutexvar_pd(last_d, p1));
    const __m512 r = _mm512_loadu_ps(range + kk);
    const __m512 p_r = prefix_max16(_mm512_mask_mov_ps(neg_inf, take, r));
    const __mmask16 below = _mm512_cmp_ps_mask(r, _mm512_max_ps(p_r, r_carry), _CMP_LT_OQ);
    r_carry = _mm512_max_ps(r_carry, _mm512_permutexvar_ps(last_f, p_r));
    __m128i out = _mm_or_si128(f, _mm_maskz_mov_epi8(take & above, shadow_bit));
    out = _mm_or_si128(out, _mm_maskz_mov_epi8(take & below, layover_bit));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(flags + kk), out);
  }
  cot_min = _mm512_cvtsd_f64(carry);
  max_r = _mm512_cvtss_f32(r_carry);
}

// backward_scan over samples [0, n), n a multiple of 16.
RIS_AVX512_KERNEL void backward_scan_avx512(int n, const float* __restrict range,
                                            std::uint8_t* __restrict flags, float min_r) {
  const __m512 inf = _mm512_set1_ps(std::numeric_limits<float>::infinity());
  const __m128i skip = _mm_set1_epi8(static_cast<char>(kSkip));
  const __m128i layover_bit = _mm_set1_epi8(static_cast<char>(sample_flag::kLayover));
  __m512 carry = _mm512_set1_ps(min_r);
  for (int k = n - 16; k >= 0; k -= 16) {
    const auto kk = static_cast<std::size_t>(k);
    const __m128i f = _mm_loadu_si128(reinterpret_cast<const __m128i*>(flags + kk));
    const __mmask16 take = _mm_testn_epi8_mask(f, skip);
    const __m512 r = _mm512_loadu_ps(range + kk);
    const __m512 s = suffix_min16(_mm512_mask_mov_ps(inf, take, r));
    const __mmask16 above = _mm512_cmp_ps_mask(r, _mm512_min_ps(s, carry), _CMP_GT_OQ);
    carry = _mm512_min_ps(carry, _mm512_permutexvar_ps(_mm512_setzero_si512(), s));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(flags + kk),
                     _mm_or_si128(f, _mm_maskz_mov_epi8(take & above, layover_bit)));
  }
}
#endif

}  // namespace

void mark_shadow_and_layover(const LineSamples& l, ScanKernel kernel) {
  // Cast shadow: a point is shadowed when a nearer point has a larger look
  // angle from nadir psi = atan2(u, H - h) (MODEL.md section 2: t = tan psi =
  // u / (H - h) where H > h). For u > 0 (every sample taken: the callers flag
  // u <= 0 kUnseen) cot psi = (H - h) / u decreases strictly with psi over
  // (0, pi), so psi_max > psi <=> cot psi > min of the nearer samples' cot
  // psi: a running minimum instead of the horizon's cross product, valid
  // also for terrain above the antenna (H - h < 0: a PPI on a mast among
  // hills). Equal angles shadow nothing, as before.
  // Layover, SNAP definition: near to far keeping the largest R, a smaller R
  // is layover; far to near keeping the smallest R, a larger R is layover.
  // Both running scans sixteen (AVX-512) or eight samples at a time; the
  // samples after the last full block one by one, the same comparisons.
  // The arrays in locals: flags are bytes, whose stores may alias anything
  // (the LineSamples itself, for all the compiler knows).
  std::uint8_t* __restrict flags = l.flags;
  const float* __restrict range = l.slant_range_m;
  const float* __restrict height = l.height_m;
  bool wide = false;
#ifdef RIS_HAVE_AVX512_KERNELS
  wide = cpu_has_avx512() && kernel == ScanKernel::best;
#endif
  const int lanes = wide ? 16 : kLanes;
  const int full = l.samples / lanes * lanes;
  double cot_min = std::numeric_limits<double>::infinity();
  float max_r = -std::numeric_limits<float>::infinity();
  if (wide) {
#ifdef RIS_HAVE_AVX512_KERNELS
    forward_scan_avx512(full, l.first_u_m, l.step_m, l.altitude_m, height, range, flags, cot_min,
                        max_r);
#endif
  } else {
    // The cotangents a block at a time (a loop that vectorises), then the
    // scan.
    constexpr int kBlock = 256;
    double cot[kBlock];
    for (int j0 = 0; j0 < full; j0 += kBlock) {
      const int n = std::min(kBlock, full - j0);
      cot_look_angle(j0, n, l.first_u_m, l.step_m, l.altitude_m, height, flags, cot);
      forward_scan(n, cot, range + j0, flags + j0, cot_min, max_r);
    }
  }
  for (int j = full; j < l.samples; ++j) {
    const bool take = !(flags[j] & kSkip);
    const double cot =
        cot_look_angle_at(j, l.first_u_m, l.step_m, l.altitude_m, height[j], flags[j]);
    const float r = range[j];
    std::uint8_t f = flags[j];
    if (take && cot > cot_min) f |= sample_flag::kShadow;
    if (take && r < max_r) f |= sample_flag::kLayover;
    flags[j] = f;
    cot_min = std::min(cot_min, cot);
    max_r = std::max(max_r, take ? r : max_r);
  }
  float min_r = std::numeric_limits<float>::infinity();
  for (int j = l.samples - 1; j >= full; --j) {
    const bool take = !(flags[j] & kSkip);
    const float r = range[j];
    if (take && r > min_r) flags[j] |= sample_flag::kLayover;
    min_r = std::min(min_r, take ? r : min_r);
  }
  if (wide) {
#ifdef RIS_HAVE_AVX512_KERNELS
    backward_scan_avx512(full, range, flags, min_r);
#endif
  } else {
    backward_scan(full, range, flags, min_r);
  }
}

}  // namespace ris
