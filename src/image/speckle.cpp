#include "ris/image/speckle.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "ris/util/error.h"

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace ris {

FadingField::FadingField(std::span<const double> looks_per_bin, FadingLaw law, std::uint64_t seed)
    : looks_(looks_per_bin.begin(), looks_per_bin.end()),
      sqrt_looks_(looks_per_bin.size()),
      law_(law),
      seed_(seed),
      zig_(&ziggurat_tables()) {
  // Per range bin, once: the Gamma sampler's constants and sqrt(N) (the same
  // arithmetic as fading_factor, so the same bytes).
  gamma_.reserve(looks_.size());
  squeeze_in_registers_.resize(looks_.size());
  for (std::size_t b = 0; b < looks_.size(); ++b) {
    RIS_CHECK(looks_[b] > 0.0 && std::isfinite(looks_[b]));
    gamma_.emplace_back(looks_[b]);
    sqrt_looks_[b] = std::sqrt(looks_[b]);
    squeeze_in_registers_[b] = looks_[b] >= 1.0 ? 1 : 0;
    squeeze_c_.push_back(squeeze_in_registers_[b] ? gamma_[b].c()
                                                  : std::numeric_limits<double>::quiet_NaN());
    squeeze_d_.push_back(gamma_[b].d());
  }
}

namespace {

#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define RIS_SPECKLE_AVX2 1
// FadingField::apply_line's draw in registers, four pixels at a time (AVX2:
// the ziggurat's table entries of the four layers; the arithmetic in double with separate
// multiplies and adds in the scalar code's order, so the same bytes). Writes
// the pixels it decides and returns a bit per pixel (of n <= 64) that the
// scalar path must still draw: a draw needing more words, and the last n % 4.
// No-data and non-positive pixels are left alone, as the scalar path does.
__attribute__((target("avx2"))) std::uint64_t fade_quads_avx2(
    float* row, int n, const std::uint32_t* w0, const std::uint32_t* w1, const std::uint32_t* w2,
    const ZigguratTables& zig, bool exact, const double* c, const double* d, const double* looks,
    const double* sqrt_looks) {
  const __m256d one = _mm256_set1_pd(1.0);
  const __m128i sign = _mm_set1_epi32(static_cast<int>(0x80000000u));
  std::uint64_t pending = 0;
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    const __m128 p = _mm_loadu_ps(row + i);
    const __m128 valid = _mm_and_ps(_mm_cmp_ps(p, _mm_setzero_ps(), _CMP_GT_OQ),
                                    _mm_cmp_ps(p, _mm_set1_ps(HUGE_VALF), _CMP_LT_OQ));
    // ziggurat_normal's common case.
    const __m128i hz = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w0 + i));
    const __m128i layer = _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(w1 + i)),
                                        _mm_set1_epi32(127));
    // The layers' table entries by scalar loads (AVX2 gathers were slower on
    // this EPYC, BM_Fading).
    alignas(16) std::uint32_t l[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(l), layer);
    const __m128i k = _mm_setr_epi32(static_cast<int>(zig.k[l[0]]), static_cast<int>(zig.k[l[1]]),
                                     static_cast<int>(zig.k[l[2]]), static_cast<int>(zig.k[l[3]]));
    const __m128i in_rect =  // |hz| < k, unsigned
        _mm_cmpgt_epi32(_mm_xor_si128(k, sign), _mm_xor_si128(_mm_abs_epi32(hz), sign));
    const __m256d x = _mm256_mul_pd(
        _mm256_cvtepi32_pd(hz), _mm256_setr_pd(zig.w[l[0]], zig.w[l[1]], zig.w[l[2]], zig.w[l[3]]));
    __m256d y, fast = _mm256_castsi256_pd(_mm256_cvtepi32_epi64(in_rect));
    if (exact) {
      // GammaSampler's first try and its squeeze (see apply_line).
      const __m256d v = _mm256_add_pd(one, _mm256_mul_pd(_mm256_loadu_pd(c + i), x));
      const __m256d v3 = _mm256_mul_pd(_mm256_mul_pd(v, v), v);
      const __m128i u32 = _mm_loadu_si128(reinterpret_cast<const __m128i*>(w2 + i));
      const __m256d u_int = _mm256_add_pd(_mm256_cvtepi32_pd(_mm_xor_si128(u32, sign)),
                                          _mm256_set1_pd(2147483648.0));  // the word, exactly
      const __m256d u =
          _mm256_mul_pd(_mm256_add_pd(u_int, _mm256_set1_pd(0.5)), _mm256_set1_pd(0x1.0p-32));
      const __m256d x2 = _mm256_mul_pd(x, x);
      const __m256d squeeze =
          _mm256_sub_pd(one, _mm256_mul_pd(_mm256_mul_pd(_mm256_set1_pd(0.0331), x2), x2));
      fast = _mm256_and_pd(fast, _mm256_cmp_pd(v, _mm256_setzero_pd(), _CMP_GT_OQ));
      fast = _mm256_and_pd(fast, _mm256_cmp_pd(u, squeeze, _CMP_LT_OQ));
      y = _mm256_div_pd(_mm256_mul_pd(_mm256_mul_pd(one, _mm256_loadu_pd(d + i)), v3),
                        _mm256_loadu_pd(looks + i));
    } else {
      const __m256d floor = _mm256_set1_pd(kSeedFadingFloor);
      y = _mm256_add_pd(one, _mm256_div_pd(x, _mm256_loadu_pd(sqrt_looks + i)));
      y = _mm256_blendv_pd(floor, y, _mm256_cmp_pd(y, floor, _CMP_GT_OQ));
    }
    const __m128 faded = _mm256_cvtpd_ps(_mm256_mul_pd(_mm256_cvtps_pd(p), y));
    // The four 64-bit lane masks as 32-bit ones (each lane's low half).
    const __m128 fast4 =
        _mm_shuffle_ps(_mm256_castps256_ps128(_mm256_castpd_ps(fast)),
                       _mm256_extractf128_ps(_mm256_castpd_ps(fast), 1), _MM_SHUFFLE(2, 0, 2, 0));
    _mm_storeu_ps(row + i, _mm_blendv_ps(p, faded, _mm_and_ps(valid, fast4)));
    const int slow = _mm_movemask_ps(_mm_andnot_ps(fast4, valid));
    pending |= static_cast<std::uint64_t>(slow) << i;
  }
  for (; i < n; ++i) pending |= std::uint64_t{1} << i;
  return pending;
}
#endif

// Whether any of the n pixels has a positive, finite power (the pixels
// apply_line fades; it leaves the others as they are).
bool any_to_fade(const float* row, int n) {
  bool any = false;
  for (int i = 0; i < n; ++i) any |= (row[i] > 0.0f) & (row[i] < HUGE_VALF);
  return any;
}

#ifdef RIS_SPECKLE_AVX2
// any_to_fade eight pixels at a time, stopping at the first block with one
// (GCC left the loop above scalar: 13% of apply_line's samples).
__attribute__((target("avx2"))) bool any_to_fade_avx2(const float* row, int n) {
  int i = 0;
  for (; i + 8 <= n; i += 8) {
    const __m256 p = _mm256_loadu_ps(row + i);
    const __m256 fade = _mm256_and_ps(_mm256_cmp_ps(p, _mm256_setzero_ps(), _CMP_GT_OQ),
                                      _mm256_cmp_ps(p, _mm256_set1_ps(HUGE_VALF), _CMP_LT_OQ));
    if (_mm256_movemask_ps(fade) != 0) return true;
  }
  return any_to_fade(row + i, n - i);
}
#endif

}  // namespace

void FadingField::apply_line(float* row, int line) const {
  const int bins = this->bins();
  const auto line_key = static_cast<std::uint32_t>(line);
  const bool exact = law_ == FadingLaw::exact_gamma;
  // Each pixel draws from its own counter stream (seed, bin, line): its first
  // block comes from the vectorised batch, the rest (rarely needed) from the
  // stream itself.
  constexpr int kChunk = 64;
  alignas(32) std::uint32_t w[4][kChunk];
  for (int b0 = 0; b0 < bins; b0 += kChunk) {
    const int n = std::min(kChunk, bins - b0);
    // A chunk with nothing to fade (no data or no power: an oblique track's
    // image is about half such pixels, outside the rotated scene) draws
    // nothing; every pixel has its own stream, so the others' bytes are the
    // same.
#ifdef RIS_SPECKLE_AVX2
    static const bool avx2_any = __builtin_cpu_supports("avx2");
    if (avx2_any ? !any_to_fade_avx2(row + b0, n) : !any_to_fade(row + b0, n)) continue;
#else
    if (!any_to_fade(row + b0, n)) continue;
#endif
    philox_first_blocks(seed_, static_cast<std::uint32_t>(b0), line_key, CounterRng::kFadingStream,
                        static_cast<std::size_t>(n), {w[0], w[1], w[2], w[3]});
    const ZigguratTables& zig = *zig_;
    // Which pixels the scalar path draws: all, or those the vector kernel
    // left (bit i: pixel b0 + i).
    std::uint64_t todo = n == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << n) - 1;
#ifdef RIS_SPECKLE_AVX2
    static const bool avx2 = __builtin_cpu_supports("avx2");
    if (avx2) {
      const std::size_t at = static_cast<std::size_t>(b0);
      todo = fade_quads_avx2(row + b0, n, w[0], w[1], w[2], zig, exact, squeeze_c_.data() + at,
                             squeeze_d_.data() + at, looks_.data() + at, sqrt_looks_.data() + at);
    }
#endif
    for (; todo != 0; todo &= todo - 1) {
      const int i = std::countr_zero(todo);
      const int bin = b0 + i;
      const float p = row[bin];
      if (!(p > 0.0f) || !std::isfinite(p)) continue;
      const std::size_t b = static_cast<std::size_t>(bin);
      double y = 0.0;
      bool drawn = false;
      // The words of the pixel's stream its first try used, when it ended
      // without a value (rejected, or v <= 0) and N >= 1: the sampler's next
      // try starts after them, exactly as in its own loop (a v <= 0 redraws
      // the normal from the next word, as a new try does; nothing else is
      // drawn in between and N >= 1 draws no boost). 0: draw the pixel anew.
      int words_used = 0;
      // ziggurat_normal's common case: the value's word, the layer's word.
      const auto hz = static_cast<std::int32_t>(w[0][i]);
      const std::uint32_t layer = w[1][i] & 127u;
      const std::uint32_t mag =
          hz < 0 ? 0u - static_cast<std::uint32_t>(hz) : static_cast<std::uint32_t>(hz);
      if (mag < zig.k[layer]) {
        const double x = hz * zig.w[layer];
        if (!exact) {
          y = 1.0 + x / sqrt_looks_[b];
          y = y > kSeedFadingFloor ? y : kSeedFadingFloor;
          drawn = true;
        } else if (squeeze_in_registers_[b]) {
          // GammaSampler's first try: v = (1 + c x)^3 and u from the third
          // word, accepted by its squeeze or its logarithmic test (boost 1:
          // d v).
          const GammaSampler& g = gamma_[b];
          double v = 1.0 + g.c() * x;
          words_used = 2;
          if (v > 0.0) {
            v = v * v * v;
            const double u = (static_cast<double>(w[2][i]) + 0.5) * 0x1.0p-32;
            const double x2 = x * x;
            words_used = 3;
            // The squeeze, then (as GammaSampler, with the same values) the
            // logarithmic test before any further draw.
            if (u < 1.0 - 0.0331 * x2 * x2 ||
                std::log(u) < 0.5 * x2 + g.d() * (1.0 - v + std::log(v))) {
              y = 1.0 * g.d() * v / looks_[b];
              drawn = true;
            }
          }
        }
      }
      if (!drawn) {
        // Everything else: the draw goes on from the pixel's stream (after
        // the first try's words) or starts again there.
        CounterRng rng(seed_, static_cast<std::uint32_t>(bin), line_key, CounterRng::kFadingStream,
                       {w[0][i], w[1][i], w[2][i], w[3][i]});
        for (int k = 0; k < words_used; ++k) rng.next_u32();
        if (exact) {
          y = gamma_[b](rng, zig) / looks_[b];
        } else {
          y = 1.0 + ziggurat_normal(rng, zig) / sqrt_looks_[b];
          y = y > kSeedFadingFloor ? y : kSeedFadingFloor;
        }
      }
      row[bin] = static_cast<float>(static_cast<double>(p) * y);
    }
  }
}

void apply_fading(std::span<float> power_w, int lines, int bins,
                  std::span<const double> looks_per_bin, FadingLaw law, std::uint64_t seed,
                  int first_line) {
  RIS_CHECK(lines >= 0 && bins >= 0);
  RIS_CHECK(power_w.size() == static_cast<std::size_t>(lines) * static_cast<std::size_t>(bins));
  RIS_CHECK(looks_per_bin.size() == static_cast<std::size_t>(bins));
  const FadingField fading(looks_per_bin, law, seed);
  // Lines are independent: any schedule gives the same bytes.
#pragma omp parallel for schedule(static)
  for (int line = 0; line < lines; ++line) {
    fading.apply_line(
        power_w.data() + static_cast<std::size_t>(line) * static_cast<std::size_t>(bins),
        first_line + line);
  }
}

}  // namespace ris
