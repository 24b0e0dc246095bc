#include "ris/image/slar_azimuth_integrator.h"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

#include "ris/util/error.h"
#include "ris/util/vector_clones.h"

// GCC 12's AVX-512 intrinsics pass _mm512_undefined_*() as the masked-off
// source of the unmasked forms, which -Wmaybe-uninitialized reports once they
// are inlined (GCC bug 105593, fixed in GCC 13): a false positive. (Before
// the intrinsics' headers, whose lines the warning points at.)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include "ris/util/avx512.h"
#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace ris {

SlarAzimuthIntegrator::SlarAzimuthIntegrator(const SlarImagingParams& p, double line_spacing_m,
                                             int lines, int bins, int bin_begin, int bin_end)
    : lines_(lines), bin0_(bin_begin) {
  if (bin_end < 0) bin_end = bins;
  RIS_CHECK(lines > 0 && bins > 0 && 0 <= bin_begin && bin_begin < bin_end && bin_end <= bins);
  bins_ = bin_end - bin_begin;
  threaded_ = bins_ == bins;
  half_.resize(static_cast<std::size_t>(bins_));
  double half_max = 0.0;
  for (int b = 0; b < bins_; ++b) {
    // The image's bin number: the same footprint as the whole integrator's.
    const int image_bin = bin0_ + b;
    const double half =
        p.azimuth_window_lines > 0.0
            ? 0.5 * p.azimuth_window_lines
            : 0.5 * slar_footprint_m(p.range.centre_m(image_bin), p.azimuth_beamwidth_rad) /
                  line_spacing_m;
    half_[static_cast<std::size_t>(b)] = half;
    if (std::isfinite(half)) half_max = std::max(half_max, half);
  }
  // A footprint longer than the image reaches every line anyway.
  margin_ = static_cast<int>(std::min(std::ceil(half_max), double(lines))) + 2;
  extent_.resize(static_cast<std::size_t>(lines));
  // Running-sum row 0: nothing summed yet.
  const std::size_t n = static_cast<std::size_t>(bins);
  cum_.assign(n, 0.0);
  cum_area_.assign(n, 0.0);
  cum_data_.assign(n, 0);
  cum_visible_.assign(n, 0);
  cum_layover_.assign(n, 0);
}

std::pair<int, int> SlarAzimuthIntegrator::active_bins(int k) const {
  // Pixel k reads the running sums of lines within ceil(half) + 1 < M of it
  // (emit_pixel: the integral's rows and the mask's strips); every one of
  // those lines is pushed when k is emitted (lines_ready).
  const int j0 = std::max(0, k - margin_), j1 = std::min(pushed_ - 1, k + margin_);
  int lo = bins_, hi = 0;
  for (int j = j0; j <= j1; ++j) {
    const auto [l, h] = extent_[static_cast<std::size_t>(j)];
    if (l < h) {
      lo = std::min(lo, l);
      hi = std::max(hi, h);
    }
  }
  return lo < hi ? std::pair{lo, hi} : std::pair{0, 0};
}

std::size_t SlarAzimuthIntegrator::row(int cum_index) const {
  return static_cast<std::size_t>(cum_index - base_) * static_cast<std::size_t>(bins_);
}

namespace {

// One running-sum row of push(): its five arrays.
struct CumRow {
  double* power;
  double* area;
  int* data;
  int* visible;
  int* layover;
};

// Running-sum row j + 1 = row j + line j's profile, over n bins. A function
// of its own with restrict-qualified arrays so that it vectorises (the
// member loop did not: the byte loads may alias the rows); the same
// additions, so the same bytes.
RIS_VECTOR_CLONES void push_row_kernel(
    int n, const std::uint8_t* __restrict touch, const float* __restrict power,
    const float* __restrict area, const double* __restrict p_power, const double* __restrict p_area,
    const int* __restrict p_data, const int* __restrict p_visible, const int* __restrict p_layover,
    double* __restrict n_power, double* __restrict n_area, int* __restrict n_data,
    int* __restrict n_visible, int* __restrict n_layover) {
  for (int b = 0; b < n; ++b) {
    const int t = touch[b];
    n_power[b] = p_power[b] + double(power[b]);
    n_area[b] = p_area[b] + double(area[b]);
    n_data[b] = p_data[b] + ((t & slar_touch::kData) != 0);
    n_visible[b] = p_visible[b] + ((t & slar_touch::kVisible) != 0);
    n_layover[b] = p_layover[b] + ((t & slar_touch::kLayover) != 0);
  }
}

// The bins [lo, hi) of a profile row outside which its touch, power and
// area bits are all zero ({0, 0} when all are): from both ends eight bins
// at a time as 64-bit words (a loop over every bin with min / max
// reductions did not vectorise); the row is in L1 after push_row_kernel.
std::pair<int, int> row_extent(int n, const std::uint8_t* touch, const float* power,
                               const float* area) {
  const auto word = [](const void* at) {
    std::uint64_t w = 0;
    std::memcpy(&w, at, sizeof w);
    return w;
  };
  const auto zero8 = [&](int b) {
    const float* p = power + b;
    const float* a = area + b;
    return (word(touch + b) | word(p) | word(p + 2) | word(p + 4) | word(p + 6) | word(a) |
            word(a + 2) | word(a + 4) | word(a + 6)) == 0;
  };
  const auto zero1 = [&](int b) {
    std::uint32_t p = 0, a = 0;
    std::memcpy(&p, power + b, sizeof p);
    std::memcpy(&a, area + b, sizeof a);
    return (touch[b] | p | a) == 0;
  };
  int lo = 0;
  while (lo + 8 <= n && zero8(lo)) lo += 8;
  while (lo < n && zero1(lo)) ++lo;
  if (lo == n) return {0, 0};
  int hi = n;
  while (hi - 8 >= lo && zero8(hi - 8)) hi -= 8;
  while (zero1(hi - 1)) --hi;  // stops at lo + 1 at the latest
  return {lo, hi};
}

// push_row_kernel on a row of running sums; returns row_extent.
inline std::pair<int, int> push_row(int n, const std::uint8_t* touch, const float* power,
                                    const float* area, const CumRow& prev, const CumRow& next) {
  push_row_kernel(n, touch, power, area, prev.power, prev.area, prev.data, prev.visible,
                  prev.layover, next.power, next.area, next.data, next.visible, next.layover);
  return row_extent(n, touch, power, area);
}

}  // namespace

void SlarAzimuthIntegrator::push(const SlarLineProfiles& prof, int count) {
  RIS_CHECK(prof.bins >= bin0_ + bins_ && count >= 0 && pushed_ + count <= lines_);
  RIS_CHECK(!threaded_ || prof.bins == bins_);
  RIS_CHECK(prof.line0 <= pushed_ && pushed_ + count <= prof.line0 + prof.lines);
  if (count == 0) return;
  const std::size_t n =
      static_cast<std::size_t>(pushed_ + count + 1 - base_) * static_cast<std::size_t>(bins_);
  cum_.resize(n);
  cum_area_.resize(n);
  cum_data_.resize(n);
  cum_visible_.resize(n);
  cum_layover_.resize(n);
  // Each thread sums its own bins over the lines, in line order (the
  // arithmetic of a pixel does not depend on the thread count), and finds
  // each line's extent within them; the extents are merged after.
  const int max_threads = threaded_ ? omp_get_max_threads() : 1;
  part_extent_.assign(static_cast<std::size_t>(max_threads) * static_cast<std::size_t>(count),
                      {bins_, 0});
#pragma omp parallel if (threaded_)
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
    const int b0 = static_cast<int>(std::int64_t(bins_) * t / nt);
    const int b1 = static_cast<int>(std::int64_t(bins_) * (t + 1) / nt);
    for (int j = pushed_; j < pushed_ + count; ++j) {
      const std::size_t in = prof.index(j, bin0_) + static_cast<std::size_t>(b0);
      const std::size_t prev = row(j) + static_cast<std::size_t>(b0);
      const std::size_t next = row(j + 1) + static_cast<std::size_t>(b0);
      const auto [lo, hi] = push_row(
          b1 - b0, prof.touch.data() + in, prof.power_w.data() + in, prof.area_m2.data() + in,
          {cum_.data() + prev, cum_area_.data() + prev, cum_data_.data() + prev,
           cum_visible_.data() + prev, cum_layover_.data() + prev},
          {cum_.data() + next, cum_area_.data() + next, cum_data_.data() + next,
           cum_visible_.data() + next, cum_layover_.data() + next});
      if (lo < hi) {
        part_extent_[static_cast<std::size_t>(t) * static_cast<std::size_t>(count) +
                     static_cast<std::size_t>(j - pushed_)] = {b0 + lo, b0 + hi};
      }
    }
  }
  for (int k = 0; k < count; ++k) {
    int lo = bins_, hi = 0;
    for (int t = 0; t < max_threads; ++t) {
      const auto [l, h] =
          part_extent_[static_cast<std::size_t>(t) * static_cast<std::size_t>(count) +
                       static_cast<std::size_t>(k)];
      lo = std::min(lo, l);
      hi = std::max(hi, h);
    }
    extent_[static_cast<std::size_t>(pushed_ + k)] = lo < hi ? std::pair{lo, hi} : std::pair{0, 0};
  }
  pushed_ += count;
}

int SlarAzimuthIntegrator::lines_ready() const {
  if (pushed_ == lines_) return lines_ - emitted_;
  // Line k needs running sums up to index k + M (see the header).
  return std::max(0, pushed_ - margin_ + 1 - emitted_);
}

namespace {

// What emit() reads: the running sums (rows of `bins`, the first kept one
// being running-sum index `base`), the footprint's half length per bin and
// the image's line count.
struct EmitRows {
  const double* cum;
  const double* cum_area;
  const int* cum_data;
  const int* cum_visible;
  const int* cum_layover;
  const double* half;
  int base;
  int bins;
  int lines;
  std::size_t row(int cum_index) const {
    return static_cast<std::size_t>(cum_index - base) * static_cast<std::size_t>(bins);
  }
};

// Pixel (line k, bin b) of emit(): the profile integrated over
// [k - half, k + half] by the running sums, and the mask from the lines whose
// strip overlaps it.
inline void emit_pixel(const EmitRows& r, int k, int b, float* power, float* area,
                       std::uint8_t* mask) {
  const int n = r.lines;
  const std::size_t bb = static_cast<std::size_t>(b);
  // Integral of the profile from -1/2 to x (line units), clamped.
  const auto integral = [&](const double* c, double x) {
    const double y = std::clamp(x + 0.5, 0.0, double(n));
    const int i = std::min(static_cast<int>(y), n - 1);
    const double f = y - i;
    const std::size_t lo = r.row(i) + bb, hi = r.row(i + 1) + bb;
    return c[lo] + f * (c[hi] - c[lo]);
  };
  const double half = r.half[bb];
  const double a = k - half, e = k + half;
  power[bb] = static_cast<float>(integral(r.cum, e) - integral(r.cum, a));
  area[bb] = static_cast<float>(integral(r.cum_area, e) - integral(r.cum_area, a));
  // Lines whose strip overlaps the footprint: j + 1/2 > a and j - 1/2 < e.
  const int j_lo = std::max(0, static_cast<int>(std::floor(a - 0.5)) + 1);
  const int j_hi = std::min(n - 1, static_cast<int>(std::ceil(e + 0.5)) - 1);
  const std::size_t lo = r.row(j_lo) + bb, hi = r.row(j_hi + 1) + bb;
  const int data = r.cum_data[hi] - r.cum_data[lo];
  const int visible = r.cum_visible[hi] - r.cum_visible[lo];
  const int layover = r.cum_layover[hi] - r.cum_layover[lo];
  std::uint8_t m = 0;
  if (data == 0) m |= pixel_flag::kNoData;
  if (data > 0 && visible == 0) m |= pixel_flag::kShadow;
  if (layover > 0) m |= pixel_flag::kLayover;
  mask[bb] = m;
}

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RIS_AZIMUTH_AVX2 1

// Helpers of emit_line_avx2 (lambdas would not inherit its target).
__attribute__((target("avx2"))) inline bool all_lanes_equal(__m128i v) {
  return _mm_movemask_epi8(_mm_cmpeq_epi32(v, _mm_shuffle_epi32(v, 0))) == 0xffff;
}
// c[at] + f (c[at + stride] - c[at]) for four neighbouring bins.
__attribute__((target("avx2"))) inline __m256d integral4(const double* c, std::size_t at,
                                                         std::size_t stride, __m256d f) {
  const __m256d c0 = _mm256_loadu_pd(c + at), c1 = _mm256_loadu_pd(c + at + stride);
  return _mm256_add_pd(c0, _mm256_mul_pd(f, _mm256_sub_pd(c1, c0)));
}
__attribute__((target("avx2"))) inline __m128i count4(const int* c, std::size_t lo,
                                                      std::size_t hi) {
  return _mm_sub_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(c + hi)),
                       _mm_loadu_si128(reinterpret_cast<const __m128i*>(c + lo)));
}

// emit()'s per-pixel rule four bins at a time. The footprint grows slowly
// with range, so four neighbouring bins almost always read the same rows of
// the running sums (the same i at both window ends and the same line
// strips): those take contiguous vector loads; the arithmetic is the scalar
// rule's, in double with separate multiplies and adds, so the same bytes.
// A block whose rows differ takes emit_pixel bin by bin. Bins [begin, end);
// returns the first bin not done (the last (end - begin) % 4 are left to the
// caller).
__attribute__((target("avx2"))) int emit_line_avx2(const EmitRows& r, int k, int begin, int end,
                                                   float* power, float* area, std::uint8_t* mask) {
  const __m256d zero = _mm256_setzero_pd(), half_line = _mm256_set1_pd(0.5);
  const __m256d lines_d = _mm256_set1_pd(double(r.lines));
  const __m128i last = _mm_set1_epi32(r.lines - 1);
  const __m256d kd = _mm256_set1_pd(double(k));
  const std::size_t stride = static_cast<std::size_t>(r.bins);
  int b = begin;
  for (; b + 4 <= end; b += 4) {
    const __m256d half = _mm256_loadu_pd(r.half + b);
    const __m256d a = _mm256_sub_pd(kd, half), e = _mm256_add_pd(kd, half);
    // std::clamp(x + 1/2, 0, n): max(0, .) keeps -0 as clamp does, then min(n, .).
    const __m256d ya = _mm256_min_pd(lines_d, _mm256_max_pd(zero, _mm256_add_pd(a, half_line)));
    const __m256d ye = _mm256_min_pd(lines_d, _mm256_max_pd(zero, _mm256_add_pd(e, half_line)));
    const __m128i ia = _mm_min_epi32(_mm256_cvttpd_epi32(ya), last);
    const __m128i ie = _mm_min_epi32(_mm256_cvttpd_epi32(ye), last);
    // Lines whose strip overlaps the footprint (see the scalar rule).
    const __m128i j_lo = _mm_max_epi32(
        _mm_setzero_si128(),
        _mm_add_epi32(_mm256_cvttpd_epi32(_mm256_floor_pd(_mm256_sub_pd(a, half_line))),
                      _mm_set1_epi32(1)));
    const __m128i j_hi = _mm_min_epi32(
        last, _mm_sub_epi32(_mm256_cvttpd_epi32(_mm256_ceil_pd(_mm256_add_pd(e, half_line))),
                            _mm_set1_epi32(1)));
    if (!(all_lanes_equal(ia) && all_lanes_equal(ie) && all_lanes_equal(j_lo) &&
          all_lanes_equal(j_hi))) {
      // The rows differ within the block: the scalar rule, bin by bin.
      for (int bb = b; bb < b + 4; ++bb) emit_pixel(r, k, bb, power, area, mask);
      continue;
    }
    const std::size_t ra = r.row(_mm_cvtsi128_si32(ia)) + static_cast<std::size_t>(b);
    const std::size_t re = r.row(_mm_cvtsi128_si32(ie)) + static_cast<std::size_t>(b);
    const __m256d fa = _mm256_sub_pd(ya, _mm256_cvtepi32_pd(ia));
    const __m256d fe = _mm256_sub_pd(ye, _mm256_cvtepi32_pd(ie));
    _mm_storeu_ps(power + b, _mm256_cvtpd_ps(_mm256_sub_pd(integral4(r.cum, re, stride, fe),
                                                           integral4(r.cum, ra, stride, fa))));
    _mm_storeu_ps(area + b, _mm256_cvtpd_ps(_mm256_sub_pd(integral4(r.cum_area, re, stride, fe),
                                                          integral4(r.cum_area, ra, stride, fa))));
    const std::size_t lo = r.row(_mm_cvtsi128_si32(j_lo)) + static_cast<std::size_t>(b);
    const std::size_t hi = r.row(_mm_cvtsi128_si32(j_hi) + 1) + static_cast<std::size_t>(b);
    const __m128i data = count4(r.cum_data, lo, hi), visible = count4(r.cum_visible, lo, hi),
                  layover = count4(r.cum_layover, lo, hi);
    const __m128i z = _mm_setzero_si128();
    const __m128i no_data = _mm_cmpeq_epi32(data, z);
    const __m128i shadow = _mm_and_si128(_mm_cmpgt_epi32(data, z), _mm_cmpeq_epi32(visible, z));
    const __m128i laid = _mm_cmpgt_epi32(layover, z);
    const __m128i m =
        _mm_or_si128(_mm_or_si128(_mm_and_si128(no_data, _mm_set1_epi32(pixel_flag::kNoData)),
                                  _mm_and_si128(shadow, _mm_set1_epi32(pixel_flag::kShadow))),
                     _mm_and_si128(laid, _mm_set1_epi32(pixel_flag::kLayover)));
    const __m128i m16 = _mm_packus_epi32(m, m);
    const int m8 = _mm_cvtsi128_si32(_mm_packus_epi16(m16, m16));
    std::memcpy(mask + b, &m8, 4);
  }
  return b;
}

// emit_line_avx2 eight bins at a time with AVX-512 (the same operations in
// the same order, eight lanes; the mask bytes from mask registers): about
// half the instructions per bin. The caller finishes with emit_line_avx2's
// quads and emit_pixel.
RIS_AVX512_KERNEL inline bool all_lanes_equal8(__m256i v) {
  return _mm256_cmpeq_epi32_mask(v, _mm256_permutevar8x32_epi32(v, _mm256_setzero_si256())) == 0xff;
}
RIS_AVX512_KERNEL inline __m512d integral8(const double* c, std::size_t at, std::size_t stride,
                                           __m512d f) {
  const __m512d c0 = _mm512_loadu_pd(c + at), c1 = _mm512_loadu_pd(c + at + stride);
  return _mm512_add_pd(c0, _mm512_mul_pd(f, _mm512_sub_pd(c1, c0)));
}
RIS_AVX512_KERNEL inline __m256i count8(const int* c, std::size_t lo, std::size_t hi) {
  return _mm256_sub_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(c + hi)),
                          _mm256_loadu_si256(reinterpret_cast<const __m256i*>(c + lo)));
}

RIS_AVX512_KERNEL int emit_line_avx512(const EmitRows& r, int k, int begin, int end, float* power,
                                       float* area, std::uint8_t* mask) {
  const __m512d zero = _mm512_setzero_pd(), half_line = _mm512_set1_pd(0.5);
  const __m512d lines_d = _mm512_set1_pd(double(r.lines));
  const __m256i last = _mm256_set1_epi32(r.lines - 1);
  const __m512d kd = _mm512_set1_pd(double(k));
  const std::size_t stride = static_cast<std::size_t>(r.bins);
  constexpr int kFloor = _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC;
  constexpr int kCeil = _MM_FROUND_TO_POS_INF | _MM_FROUND_NO_EXC;
  int b = begin;
  for (; b + 8 <= end; b += 8) {
    const __m512d half = _mm512_loadu_pd(r.half + b);
    const __m512d a = _mm512_sub_pd(kd, half), e = _mm512_add_pd(kd, half);
    const __m512d ya = _mm512_min_pd(lines_d, _mm512_max_pd(zero, _mm512_add_pd(a, half_line)));
    const __m512d ye = _mm512_min_pd(lines_d, _mm512_max_pd(zero, _mm512_add_pd(e, half_line)));
    const __m256i ia = _mm256_min_epi32(_mm512_cvttpd_epi32(ya), last);
    const __m256i ie = _mm256_min_epi32(_mm512_cvttpd_epi32(ye), last);
    const __m256i j_lo = _mm256_max_epi32(
        _mm256_setzero_si256(), _mm256_add_epi32(_mm512_cvttpd_epi32(_mm512_roundscale_pd(
                                                     _mm512_sub_pd(a, half_line), kFloor)),
                                                 _mm256_set1_epi32(1)));
    const __m256i j_hi = _mm256_min_epi32(
        last, _mm256_sub_epi32(
                  _mm512_cvttpd_epi32(_mm512_roundscale_pd(_mm512_add_pd(e, half_line), kCeil)),
                  _mm256_set1_epi32(1)));
    if (!(all_lanes_equal8(ia) && all_lanes_equal8(ie) && all_lanes_equal8(j_lo) &&
          all_lanes_equal8(j_hi))) {
      for (int bb = b; bb < b + 8; ++bb) emit_pixel(r, k, bb, power, area, mask);
      continue;
    }
    const std::size_t ra = r.row(_mm256_cvtsi256_si32(ia)) + static_cast<std::size_t>(b);
    const std::size_t re = r.row(_mm256_cvtsi256_si32(ie)) + static_cast<std::size_t>(b);
    const __m512d fa = _mm512_sub_pd(ya, _mm512_cvtepi32_pd(ia));
    const __m512d fe = _mm512_sub_pd(ye, _mm512_cvtepi32_pd(ie));
    _mm256_storeu_ps(power + b, _mm512_cvtpd_ps(_mm512_sub_pd(integral8(r.cum, re, stride, fe),
                                                              integral8(r.cum, ra, stride, fa))));
    _mm256_storeu_ps(area + b,
                     _mm512_cvtpd_ps(_mm512_sub_pd(integral8(r.cum_area, re, stride, fe),
                                                   integral8(r.cum_area, ra, stride, fa))));
    const std::size_t lo = r.row(_mm256_cvtsi256_si32(j_lo)) + static_cast<std::size_t>(b);
    const std::size_t hi = r.row(_mm256_cvtsi256_si32(j_hi) + 1) + static_cast<std::size_t>(b);
    const __m256i data = count8(r.cum_data, lo, hi), visible = count8(r.cum_visible, lo, hi),
                  layover = count8(r.cum_layover, lo, hi);
    const __m256i z = _mm256_setzero_si256();
    const __mmask8 no_data = _mm256_cmpeq_epi32_mask(data, z);
    const __mmask8 shadow = static_cast<__mmask8>(_mm256_cmpgt_epi32_mask(data, z) &
                                                  _mm256_cmpeq_epi32_mask(visible, z));
    const __mmask8 laid = _mm256_cmpgt_epi32_mask(layover, z);
    const __m128i m = _mm_or_si128(
        _mm_or_si128(
            _mm_maskz_mov_epi8(no_data, _mm_set1_epi8(static_cast<char>(pixel_flag::kNoData))),
            _mm_maskz_mov_epi8(shadow, _mm_set1_epi8(static_cast<char>(pixel_flag::kShadow)))),
        _mm_maskz_mov_epi8(laid, _mm_set1_epi8(static_cast<char>(pixel_flag::kLayover))));
    _mm_storel_epi64(reinterpret_cast<__m128i*>(mask + b), m);
  }
  return b;
}
#endif

}  // namespace

void SlarAzimuthIntegrator::emit(int count, float* mean_power_w, float* area_m2, std::uint8_t* mask,
                                 std::size_t row_stride) {
  RIS_CHECK(count >= 0 && count <= lines_ready());
  const int bins = bins_;
  const std::size_t stride = row_stride > 0 ? row_stride : static_cast<std::size_t>(bins);
  const EmitRows rows{cum_.data(),
                      cum_area_.data(),
                      cum_data_.data(),
                      cum_visible_.data(),
                      cum_layover_.data(),
                      half_.data(),
                      base_,
                      bins,
                      lines_};
  const int first = emitted_;
#ifdef RIS_AZIMUTH_AVX2
  static const bool avx2 = __builtin_cpu_supports("avx2");
  static const bool avx512 = cpu_has_avx512();
#endif
  // Dynamic blocks of lines (see render_slar); each line is independent.
#pragma omp parallel for schedule(dynamic, 16) if (threaded_)
  for (int k = first; k < first + count; ++k) {
    const std::size_t out = static_cast<std::size_t>(k - first) * stride;
    float* const power = mean_power_w + out;
    float* const area = area_m2 + out;
    std::uint8_t* const m = mask + out;
    // Outside the data extents of the lines within M of line k the
    // footprint holds no data (see active_bins): the pixel's rule gives
    // +0 W, +0 m^2 and kNoData there, written directly. The bins computed
    // start and end on a multiple of four, as the vector blocks.
    const auto [lo, hi] = active_bins(k);
    const int begin = lo / 4 * 4;
    const int end = std::min(bins, (hi + 3) / 4 * 4);
    std::fill(power, power + begin, 0.0f);
    std::fill(area, area + begin, 0.0f);
    std::fill(m, m + begin, pixel_flag::kNoData);
    int b0 = begin;
#ifdef RIS_AZIMUTH_AVX2
    if (avx512) b0 = emit_line_avx512(rows, k, b0, end, power, area, m);
    if (avx2) b0 = emit_line_avx2(rows, k, b0, end, power, area, m);
#endif
    for (int b = b0; b < end; ++b) emit_pixel(rows, k, b, power, area, m);
    std::fill(power + end, power + bins, 0.0f);
    std::fill(area + end, area + bins, 0.0f);
    std::fill(m + end, m + bins, pixel_flag::kNoData);
  }
  emitted_ += count;
  // Drop the running sums no later line needs (indices below emitted_ - M).
  const int keep_from = std::max(base_, std::min(emitted_ - margin_, pushed_));
  if (keep_from > base_) {
    const auto drop = static_cast<std::ptrdiff_t>(row(keep_from));
    cum_.erase(cum_.begin(), cum_.begin() + drop);
    cum_area_.erase(cum_area_.begin(), cum_area_.begin() + drop);
    cum_data_.erase(cum_data_.begin(), cum_data_.begin() + drop);
    cum_visible_.erase(cum_visible_.begin(), cum_visible_.begin() + drop);
    cum_layover_.erase(cum_layover_.begin(), cum_layover_.begin() + drop);
    base_ = keep_from;
  }
}

}  // namespace ris
