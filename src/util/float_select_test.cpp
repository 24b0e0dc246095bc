#include "ris/util/float_select.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace ris {
namespace {

// Against std::nth_element on a filtered copy: every rank of a small set and
// the median and extremes of a large one, with negative values, duplicates,
// signed zeros, infinities, NaN and masked values; 1 and 2 threads.
TEST(FloatSelect, MatchesNthElement) {
  const int saved = omp_get_max_threads();
  std::mt19937 gen(5);
  std::normal_distribution<float> normal(0.0f, 300.0f);
  for (int n : {1, 2, 7, 1000, 300001}) {
    std::vector<float> v(static_cast<std::size_t>(n));
    std::vector<std::uint8_t> mask(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) {
      v[i] = (i % 5 == 0) ? std::round(normal(gen)) : normal(gen);  // duplicates
      if (i % 97 == 3) v[i] = std::numeric_limits<float>::quiet_NaN();
      if (i % 89 == 4) v[i] = (i % 2) ? -0.0f : 0.0f;
      if (i % 1009 == 5) v[i] = std::numeric_limits<float>::infinity();
      mask[i] = (i % 11 != 7) ? 1 : 0;
    }
    const auto keep = [&](std::size_t i) { return mask[i] && !std::isnan(v[i]); };
    std::vector<float> ref;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (keep(i)) ref.push_back(v[i]);
    ASSERT_EQ(count_kept(v.size(), keep), ref.size());
    std::vector<std::size_t> ranks;
    if (n < 100) {
      for (std::size_t k = 0; k < ref.size(); ++k) ranks.push_back(k);
    } else {
      ranks = {0, ref.size() / 2, ref.size() / 2 - 1, ref.size() - 1, 12345 % ref.size()};
    }
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      for (std::size_t k : ranks) {
        std::vector<float> copy = ref;
        std::nth_element(copy.begin(), copy.begin() + static_cast<std::ptrdiff_t>(k), copy.end());
        const std::optional<float> got = kth_smallest_float(v, k, keep);
        ASSERT_TRUE(got.has_value());
        EXPECT_EQ(*got, copy[k]) << "n " << n << " k " << k << " threads " << threads;
      }
      EXPECT_FALSE(kth_smallest_float(v, ref.size(), keep).has_value());
    }
  }
  omp_set_num_threads(saved);
}

// The two medians in two passes: the same as nth_element at (n - 1) / 2 and
// n / 2, for odd and even counts, ties across and within buckets.
TEST(FloatSelect, MedianPairMatchesNthElement) {
  std::mt19937 gen(9);
  std::normal_distribution<float> normal(100.0f, 50.0f);
  for (int n : {1, 2, 3, 4, 10, 1001, 200000, 200001}) {
    std::vector<float> v(static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < v.size(); ++i)
      v[i] = (i % 3 == 0) ? std::round(normal(gen)) : normal(gen);
    if (n == 4) v = {1.0f, 1.0f + 1e-6f, 1.0f, 7e3f};
    const auto keep = [&](std::size_t i) { return i % 7 != 5; };
    std::vector<float> ref;
    for (std::size_t i = 0; i < v.size(); ++i)
      if (keep(i)) ref.push_back(v[i]);
    const std::size_t lo = (ref.size() - 1) / 2, hi = ref.size() / 2;
    std::vector<float> a = ref, b = ref;
    std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(lo), a.end());
    std::nth_element(b.begin(), b.begin() + static_cast<std::ptrdiff_t>(hi), b.end());
    const auto m = median_pair_float(v, keep);
    ASSERT_TRUE(m.has_value());
    EXPECT_EQ(m->first, a[lo]) << n;
    EXPECT_EQ(m->second, b[hi]) << n;
  }
  const std::vector<float> none = {1.0f};
  EXPECT_FALSE(median_pair_float(none, [](std::size_t) { return false; }).has_value());
}

// Values keep() rejects are counted in a bucket no kept value can reach
// (the top 16 bits of the all-ones NaN): long runs of rejected values, kept
// values at the top of the range (+inf, FLT_MAX), a size that is not a
// multiple of the counting chunk, 1 and 2 threads.
TEST(FloatSelect, RejectedValuesNeverCount) {
  const int saved = omp_get_max_threads();
  const float inf = std::numeric_limits<float>::infinity();
  const float all_ones_nan = std::bit_cast<float>(0x7fffffffu);
  std::vector<float> v(5003, all_ones_nan);
  std::vector<std::uint8_t> keep_mask(v.size(), 0);
  const std::vector<float> kept = {inf, std::numeric_limits<float>::max(), 3.0f, -inf, 3.0f, inf};
  for (std::size_t k = 0; k < kept.size(); ++k) {
    const std::size_t i = 17 + 997 * k;  // one value in every few chunks
    v[i] = kept[k];
    keep_mask[i] = 1;
  }
  v[4000] = 7.0f;  // rejected by the mask, not by its value
  const auto keep = [&](std::size_t i) { return (keep_mask[i] != 0) & !std::isnan(v[i]); };
  std::vector<float> sorted = kept;
  std::sort(sorted.begin(), sorted.end());
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    for (std::size_t k = 0; k < sorted.size(); ++k)
      EXPECT_EQ(*kth_smallest_float(v, k, keep), sorted[k]);
    EXPECT_FALSE(kth_smallest_float(v, sorted.size(), keep).has_value());
    const auto m = median_pair_float(v, keep);
    ASSERT_TRUE(m.has_value());
    EXPECT_EQ(m->first, sorted[2]);
    EXPECT_EQ(m->second, sorted[3]);
  }
  omp_set_num_threads(saved);
}

// The one-read sampled median (Floyd-Rivest bracket): on a terrain-like
// field and on noise with duplicates, signed zeros and masked values, its
// bracket holds the median and it equals nth_element, 1 and 2 threads, with
// samples of several sizes (and the data smaller than two samples: every
// value is the sample).
TEST(FloatSelect, SampledMedianBracketsAndMatchesNthElement) {
  const int saved = omp_get_max_threads();
  std::mt19937 gen(11);
  std::normal_distribution<float> normal(0.0f, 40.0f);
  for (int field : {0, 1}) {
    const std::size_t n = 250007;
    std::vector<float> v(n);
    float walk = 300.0f;
    for (std::size_t i = 0; i < n; ++i) {
      walk += 0.05f * normal(gen);  // a random walk: neighbours alike, as terrain
      v[i] = field == 0 ? walk : ((i % 4 == 0) ? std::round(normal(gen)) : normal(gen));
      if (field == 1 && i % 53 == 2) v[i] = (i % 2) ? -0.0f : 0.0f;
    }
    const auto keep = [&](std::size_t i) { return (i % 13 != 6) & !std::isnan(v[i]); };
    std::vector<std::uint32_t> ref;
    for (std::size_t i = 0; i < n; ++i)
      if (keep(i)) ref.push_back(detail::float_order_key(v[i]));
    const std::size_t lo = (ref.size() - 1) / 2, hi = ref.size() / 2;
    std::nth_element(ref.begin(), ref.begin() + static_cast<std::ptrdiff_t>(lo), ref.end());
    const float want_lo = detail::float_from_order_key(ref[lo]);
    std::nth_element(ref.begin(), ref.begin() + static_cast<std::ptrdiff_t>(hi), ref.end());
    const float want_hi = detail::float_from_order_key(ref[hi]);
    for (int threads : {1, 2}) {
      omp_set_num_threads(threads);
      for (std::size_t sample : {std::size_t{1024}, std::size_t{16384}, n}) {
        const detail::SampledMedian m =
            detail::median_pair_sampled<decltype(keep)>(v, keep, sample);
        ASSERT_TRUE(m.bracketed) << field << " sample " << sample;
        ASSERT_TRUE(m.median.has_value());
        // Bits, not ==: -0 and +0 are different answers.
        EXPECT_EQ(std::bit_cast<std::uint32_t>(m.median->first),
                  std::bit_cast<std::uint32_t>(want_lo))
            << field << " sample " << sample << " threads " << threads;
        EXPECT_EQ(std::bit_cast<std::uint32_t>(m.median->second),
                  std::bit_cast<std::uint32_t>(want_hi))
            << field << " sample " << sample << " threads " << threads;
      }
    }
  }
  omp_set_num_threads(saved);
}

// Data built so that the regular sample sees only its largest value: the
// bracket misses (the sampled select says so), and median_pair_float falls
// back to the radix select, still exact. Nothing kept gives nullopt either way.
TEST(FloatSelect, SampledMedianMissFallsBackToRadix) {
  const std::size_t sample = 1024, stride = 8, n = sample * stride + 5;
  std::vector<float> v(n);
  for (std::size_t i = 0; i < n; ++i)
    v[i] = (i % stride == stride / 2) ? 1e6f : static_cast<float>(i % 1000);
  const auto keep = [&](std::size_t i) { return !std::isnan(v[i]); };
  EXPECT_FALSE(detail::median_pair_sampled<decltype(keep)>(v, keep, sample).bracketed);
  std::vector<float> ref = v;
  const std::size_t lo = (n - 1) / 2, hi = n / 2;
  std::sort(ref.begin(), ref.end());
  const auto radix = detail::median_pair_radix<decltype(keep)>(v, keep);
  ASSERT_TRUE(radix.has_value());
  EXPECT_EQ(radix->first, ref[lo]);
  EXPECT_EQ(radix->second, ref[hi]);
  const auto m = median_pair_float(v, keep);
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->first, ref[lo]);
  EXPECT_EQ(m->second, ref[hi]);
  const auto none = [](std::size_t) { return false; };
  const detail::SampledMedian empty = detail::median_pair_sampled<decltype(none)>(v, none, sample);
  EXPECT_FALSE(empty.bracketed && empty.median.has_value());
  EXPECT_FALSE(median_pair_float(v, none).has_value());
}

TEST(FloatSelect, OrderKeysSortAsTheFloats) {
  const std::vector<float> sorted = {-std::numeric_limits<float>::infinity(),
                                     -1e30f,
                                     -2.5f,
                                     -1e-40f,
                                     -0.0f,
                                     0.0f,
                                     1e-40f,
                                     1.0f,
                                     3e38f,
                                     std::numeric_limits<float>::infinity()};
  for (std::size_t i = 0; i + 1 < sorted.size(); ++i) {
    EXPECT_LT(detail::float_order_key(sorted[i]), detail::float_order_key(sorted[i + 1])) << i;
  }
  for (float f : sorted) EXPECT_EQ(detail::float_from_order_key(detail::float_order_key(f)), f);
}

}  // namespace
}  // namespace ris
