// The k-th smallest of a large set of floats, and the two medians, by
// parallel counting passes over the data without reordering it: what
// std::nth_element gives on a filtered copy, at a fraction of the cost for
// millions of values (the ground-range reference height is the median of
// every scene cell; the automatic greytone reference the median of every
// pixel). keep(i) is called for every value: branch-free predicates (&
// rather than &&, raw pointers captured by value) let the keying loop
// vectorise.
//
// A float's bits, with the sign bit flipped for positive values and all bits
// flipped for negative ones, order as the floats do (-0 just below +0).
// kth_smallest_float is a radix select on these keys: pass 1 counts the top
// 16 bits of the kept values, which finds the bucket holding rank k; pass 2
// counts the low 16 bits within that bucket. median_pair_float usually reads
// the data once (a sample's bracket around the median, then the count below
// it and a copy of the few keys inside it; Floyd & Rivest 1975) and falls
// back to the two radix passes when the bracket misses. Each pass is split
// over OpenMP threads with per-thread counts, so the result does not depend
// on the thread count.
//
// Example (the median of the finite cells with data):
//   auto keep = [&](std::size_t i) { return valid[i] && std::isfinite(h[i]); };
//   std::size_t n = ris::count_kept(h.size(), keep);
//   if (n) float m = *ris::kth_smallest_float(h, n / 2, keep);
//   auto both = ris::median_pair_float(h, keep);  // ranks (n - 1) / 2, n / 2
#pragma once

#include <omp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "ris/kernels/vector_clones.h"

namespace ris {

namespace detail {

// Branch-free (so that loops over it vectorise): flip every bit of a
// negative float, only the sign bit of a positive one.
inline std::uint32_t float_order_key(float f) {
  std::uint32_t b = 0;
  std::memcpy(&b, &f, sizeof b);
  const auto sign = static_cast<std::uint32_t>(static_cast<std::int32_t>(b) >> 31);
  return b ^ (sign | 0x80000000u);
}

inline float float_from_order_key(std::uint32_t k) {
  const std::uint32_t b = (k & 0x80000000u) ? (k & 0x7fffffffu) : ~k;
  float f = 0.0f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}

// The key that stands for a value keep() rejects: the key of the positive
// NaN with every bit set. keep must reject NaN, so no kept value has a key
// in its top-16-bit bucket 0xffff (only NaNs do).
inline constexpr std::uint32_t kRejectedKey = 0xffffffffu;

// Values are keyed a chunk at a time, then counted from the chunk's keys,
// so the counting loop does only the increments: one element-by-element loop
// with keep's branches and the key's select was ~1 ns a value in each pass.
// The keying loop vectorises when keep() is branch-free (write it with & on
// bools, not &&, and capture raw pointers by value). Its AVX2 clone (keys
// and compares only: the same keys on any CPU) took the one-read median of
// 4 M values from 2.7 to 1.9 ms on one thread.
inline constexpr std::size_t kKeyChunk = 1024;

template <typename Keep>
RIS_VECTOR_CLONES inline void chunk_keys(const float* __restrict v, std::size_t i0, std::size_t n,
                                         Keep keep, std::uint32_t* __restrict keys) {
  for (std::size_t j = 0; j < n; ++j) {
    const std::uint32_t key = float_order_key(v[i0 + j]);
    keys[j] = keep(i0 + j) ? key : kRejectedKey;
  }
}

// Called by every thread of a parallel region: this thread's share of the
// chunks of v (schedule static, no barrier at the end), each keyed and passed
// to f(keys, n).
template <typename Keep, typename F>
void for_each_key_chunk(std::span<const float> v, Keep keep, F f) {
  const std::size_t size = v.size();
  const auto chunks = static_cast<std::int64_t>((size + kKeyChunk - 1) / kKeyChunk);
  std::uint32_t keys[kKeyChunk];
#pragma omp for schedule(static) nowait
  for (std::int64_t c = 0; c < chunks; ++c) {
    const std::size_t i0 = static_cast<std::size_t>(c) * kKeyChunk;
    const std::size_t n = std::min(kKeyChunk, size - i0);
    chunk_keys(v.data(), i0, n, keep, keys);
    f(keys, n);
  }
}

// For each chunk of keys, in parallel (schedule static over chunks; each
// thread counts into its own table, the tables summed after, so the result
// does not depend on the thread count): count(keys, n, table) adds a chunk
// to a thread's table of `copies` x `buckets` counts of type Counter, whose
// copies are summed into one before the threads' tables are. Returns the
// summed table.
template <typename Counter, typename Keep, typename Count>
std::vector<std::uint64_t> count_chunks_as(std::span<const float> v, Keep keep, std::size_t buckets,
                                           std::size_t copies, Count count) {
  std::vector<std::uint64_t> total(buckets, 0);
#pragma omp parallel
  {
    std::vector<Counter> local(copies * buckets, 0);
    for_each_key_chunk(
        v, keep, [&](const std::uint32_t* keys, std::size_t n) { count(keys, n, local.data()); });
    for (std::size_t k = 1; k < copies; ++k)
      for (std::size_t b = 0; b < buckets; ++b) local[b] += local[k * buckets + b];
#pragma omp critical(ris_float_select)
    for (std::size_t b = 0; b < buckets; ++b) total[b] += local[b];
  }
  return total;
}

// 32-bit counts per thread (half the table to clear and merge: a fixed cost
// of every call, which matters for small images) unless a thread could see
// 2^32 values.
template <typename Keep, typename Count>
std::vector<std::uint64_t> count_chunks(std::span<const float> v, Keep keep, std::size_t buckets,
                                        std::size_t copies, Count count) {
  if (v.size() <= 0xffffffffu)
    return count_chunks_as<std::uint32_t>(v, keep, buckets, copies, count);
  return count_chunks_as<std::uint64_t>(v, keep, buckets, copies, count);
}

// Pass 1: the top 16 bits of the kept values' keys, 65536 buckets. Value j
// of a chunk counts into copy j % 4 of the table: neighbouring values (a
// terrain's neighbouring cells) usually share a bucket, and in one table
// each increment would wait for the previous one's store (~4x slower).
template <typename Keep>
std::vector<std::uint64_t> count_top_buckets(std::span<const float> v, Keep keep) {
  constexpr std::size_t kB = 65536, kCopies = 4;
  static_assert(kKeyChunk % kCopies == 0);
  auto counts =
      count_chunks(v, keep, kB, kCopies, [](const std::uint32_t* keys, std::size_t n, auto* c) {
        // Unconditional: rejected values land in bucket 0xffff, cleared
        // below.
        std::size_t j = 0;
        for (; j + kCopies <= n; j += kCopies) {
          ++c[keys[j] >> 16];
          ++c[kB + (keys[j + 1] >> 16)];
          ++c[2 * kB + (keys[j + 2] >> 16)];
          ++c[3 * kB + (keys[j + 3] >> 16)];
        }
        for (; j < n; ++j) ++c[keys[j] >> 16];
      });
  counts[kRejectedKey >> 16] = 0;
  return counts;
}

// Pass 2: the low 16 bits of the kept values' keys whose top 16 bits are
// top_a (first table) or top_b (second; empty when top_b == top_a).
template <typename Keep>
std::pair<std::vector<std::uint64_t>, std::vector<std::uint64_t>> count_low_buckets(
    std::span<const float> v, Keep keep, std::uint32_t top_a, std::uint32_t top_b) {
  const bool two = top_b != top_a;
  const auto add = [=](const std::uint32_t* keys, std::size_t n, auto* c) {
    for (std::size_t j = 0; j < n; ++j) {
      const std::uint32_t top = keys[j] >> 16, low = keys[j] & 0xffffu;
      if (top == top_a) ++c[low];
      if (two && top == top_b) ++c[65536 + low];
    }
  };
  const auto count = [=](const std::uint32_t* keys, std::size_t n, auto* c) {
    // Few keys fall in either bucket (a median's bucket is a small part of
    // the range), though most chunks of a terrain hold some: groups of 32
    // keys without one are skipped by a vectorised test (a fixed-length
    // loop, so that GCC vectorises it).
    constexpr std::size_t kGroup = 32;
    std::size_t g = 0;
    for (; g + kGroup <= n; g += kGroup) {
      std::uint32_t any = 0;
      for (std::size_t j = 0; j < kGroup; ++j)
        any |= static_cast<std::uint32_t>((keys[g + j] >> 16) == top_a) |
               static_cast<std::uint32_t>((keys[g + j] >> 16) == top_b);
      if (any) add(keys + g, kGroup, c);
    }
    add(keys + g, n - g, c);
  };
  auto counts = count_chunks(v, keep, two ? 2 * 65536 : 65536, 1, count);
  std::vector<std::uint64_t> b;
  if (two) {
    b.assign(counts.begin() + 65536, counts.end());
    counts.resize(65536);
  }
  return {std::move(counts), std::move(b)};
}

// The bucket holding rank k (0-based) and the rank within it.
inline std::uint32_t bucket_of_rank(const std::vector<std::uint64_t>& counts, std::uint64_t& k) {
  for (std::uint32_t b = 0; b < counts.size(); ++b) {
    if (k < counts[b]) return b;
    k -= counts[b];
  }
  return 0xffffu;  // not reached when k < the number of kept values
}

}  // namespace detail

// How many values keep(i) accepts (i in [0, n)).
template <typename Keep>
std::size_t count_kept(std::size_t n, Keep keep) {
  std::int64_t count = 0;
#pragma omp parallel for reduction(+ : count) schedule(static)
  for (std::int64_t i = 0; i < static_cast<std::int64_t>(n); ++i)
    count += keep(static_cast<std::size_t>(i)) ? 1 : 0;
  return static_cast<std::size_t>(count);
}

// The k-th smallest (0-based) of the values v[i] that keep(i) accepts; keep
// must reject NaN. std::nullopt when fewer than k + 1 are kept.
template <typename Keep>
std::optional<float> kth_smallest_float(std::span<const float> v, std::size_t k, Keep keep) {
  std::uint64_t rank = k;
  const auto high = detail::count_top_buckets(v, keep);
  std::uint64_t kept = 0;
  for (std::uint64_t c : high) kept += c;
  if (rank >= kept) return std::nullopt;
  const std::uint32_t top = detail::bucket_of_rank(high, rank);
  const auto low = detail::count_low_buckets(v, keep, top, top).first;
  const std::uint32_t bottom = detail::bucket_of_rank(low, rank);
  return detail::float_from_order_key((top << 16) | bottom);
}

namespace detail {

// The lower and upper medians by the two-pass radix select (count_top_buckets
// then count_low_buckets): any input, a fixed cost of two reads and a
// 65536-bucket table per thread.
template <typename Keep>
std::optional<std::pair<float, float>> median_pair_radix(std::span<const float> v, Keep keep) {
  const auto high = count_top_buckets(v, keep);
  std::uint64_t n = 0;
  for (std::uint64_t c : high) n += c;
  if (n == 0) return std::nullopt;
  std::uint64_t r_lo = (n - 1) / 2, r_hi = n / 2;
  const std::uint32_t t_lo = bucket_of_rank(high, r_lo);
  const std::uint32_t t_hi = bucket_of_rank(high, r_hi);
  // Pass 2: the low 16 bits within the one or two buckets.
  const auto [lo_counts, hi_counts] = count_low_buckets(v, keep, t_lo, t_hi);
  const std::uint32_t b_lo = bucket_of_rank(lo_counts, r_lo);
  const std::uint32_t b_hi = bucket_of_rank(t_hi != t_lo ? hi_counts : lo_counts, r_hi);
  return std::pair{float_from_order_key((t_lo << 16) | b_lo),
                   float_from_order_key((t_hi << 16) | b_hi)};
}

// Ranks r_lo <= r_hi (0-based) of keys (reordered), all in [key_lo,
// key_hi]: a count of at most 4096 buckets of the keys' offsets from key_lo
// finds the one or two buckets holding the ranks, and nth_element on the
// few keys in them the exact keys (keys, not floats: -0 and +0 compare equal
// as floats). nth_element on all ~90k keys of a 4 M-value median's bracket
// took 0.6 ms.
inline std::pair<float, float> select_key_pair(std::vector<std::uint32_t>& keys, std::size_t r_lo,
                                               std::size_t r_hi, std::uint32_t key_lo,
                                               std::uint32_t key_hi) {
  const std::uint32_t width = key_hi - key_lo;
  const int shift = std::max(0, static_cast<int>(std::bit_width(width)) - 12);
  std::vector<std::uint32_t> counts((width >> shift) + 1, 0);
  for (std::uint32_t k : keys) ++counts[(k - key_lo) >> shift];
  // Buckets b_lo..b_hi hold ranks r_lo..r_hi (any between them are empty).
  std::size_t below = 0, b_lo = 0;
  while (below + counts[b_lo] <= r_lo) below += counts[b_lo++];
  std::size_t b_hi = b_lo, upto = below + counts[b_lo];
  while (upto <= r_hi) upto += counts[++b_hi];
  std::vector<std::uint32_t> few;
  few.reserve(upto - below);
  for (std::uint32_t k : keys) {
    const std::size_t b = (k - key_lo) >> shift;
    if (b >= b_lo && b <= b_hi) few.push_back(k);
  }
  const auto lo = few.begin() + static_cast<std::ptrdiff_t>(r_lo - below);
  std::nth_element(few.begin(), lo, few.end());
  // nth_element leaves every key after lo >= *lo: rank r_lo + 1 is their least.
  const std::uint32_t hi = r_hi == r_lo ? *lo : *std::min_element(lo + 1, few.end());
  return {float_from_order_key(*lo), float_from_order_key(hi)};
}

// The outcome of median_pair_sampled: bracketed false when the sample's
// bracket missed the median (the caller falls back to the radix select).
struct SampledMedian {
  bool bracketed = false;
  std::optional<std::pair<float, float>> median;  // nullopt: nothing kept
};

// The sample of median_pair_sampled: the keys of the kept values among
// v[stride / 2], v[stride / 2 + stride], ... (a regular grid, so the result
// never depends on a random draw or the thread count).
template <typename Keep>
std::vector<std::uint32_t> sample_keys(std::span<const float> v, Keep keep, std::size_t stride) {
  std::vector<std::uint32_t> out;
  out.reserve(v.size() / stride + 1);
  for (std::size_t i = stride / 2; i < v.size(); i += stride)
    if (keep(i)) out.push_back(float_order_key(v[i]));
  return out;
}

// Counts of one read of the data against a bracket [key_lo, key_hi] of keys:
// kept values, kept values below the bracket, and the keys inside it.
struct BracketCount {
  std::uint64_t kept = 0;
  std::uint64_t below = 0;
  std::vector<std::uint32_t> inside;
};

// One chunk's keys into c (src/util/float_select.cpp: compiled with an AVX2
// clone). A rejected key (kRejectedKey) is neither kept, below nor inside
// (key_hi < kRejectedKey).
void count_bracket_chunk(const std::uint32_t* keys, std::size_t n, std::uint32_t key_lo,
                         std::uint32_t key_hi, BracketCount& c);

// The lower and upper medians in one read of the data (Floyd & Rivest 1975,
// "Expected time bounds for selection", CACM 18(3): select from a sample two
// keys that bracket the wanted rank with high probability, then count what
// lies below the bracket and keep only what lies inside). The sample is
// about sample_size kept values on a regular grid; the bracket is the
// sample's median +- 1.5 sqrt(s) ranks, three standard deviations of a
// random sample's median rank (sqrt(s) / 2), so that ~3 / sqrt(s) of the
// values fall inside it (~60k of 4 M for s = 16384). Exact whenever
// bracketed: the result is then the median of all kept values. When the
// data is smaller than two samples, the sample is every kept value.
template <typename Keep>
SampledMedian median_pair_sampled(std::span<const float> v, Keep keep, std::size_t sample_size) {
  const std::size_t stride = std::max<std::size_t>(1, v.size() / sample_size);
  std::vector<std::uint32_t> sample = sample_keys(v, keep, stride);
  if (stride == 1) {  // every value was looked at: select among them directly
    if (sample.empty()) return {true, std::nullopt};
    const std::size_t n = sample.size();
    const auto [min, max] = std::minmax_element(sample.begin(), sample.end());
    return {true, select_key_pair(sample, (n - 1) / 2, n / 2, *min, *max)};
  }
  if (sample.empty()) return {};
  const std::size_t s = sample.size();
  const auto margin = static_cast<std::size_t>(1.5 * std::sqrt(static_cast<double>(s))) + 1;
  // The bracket's ends: sample ranks (s - 1) / 2 - margin and s / 2 + margin,
  // or the whole key range past the sample's ends.
  std::uint32_t key_lo = 0, key_hi = kRejectedKey - 1;
  if ((s - 1) / 2 >= margin) {
    const auto at = sample.begin() + static_cast<std::ptrdiff_t>((s - 1) / 2 - margin);
    std::nth_element(sample.begin(), at, sample.end());
    key_lo = *at;
  }
  if (s / 2 + margin < s) {
    const auto at = sample.begin() + static_cast<std::ptrdiff_t>(s / 2 + margin);
    std::nth_element(sample.begin(), at, sample.end());
    key_hi = *at;
  }
  // The one read, in parallel over chunks (per-thread counts and copies,
  // merged after: the keys inside are the same set whatever the threads).
  BracketCount total;
  const std::size_t size = v.size();
#pragma omp parallel
  {
    BracketCount local;
    local.inside.reserve(static_cast<std::size_t>(4.0 * static_cast<double>(size) /
                                                  std::sqrt(static_cast<double>(s))) /
                         static_cast<std::size_t>(omp_get_num_threads()));
    for_each_key_chunk(v, keep, [&](const std::uint32_t* keys, std::size_t n) {
      count_bracket_chunk(keys, n, key_lo, key_hi, local);
    });
#pragma omp critical(ris_float_select)
    {
      total.kept += local.kept;
      total.below += local.below;
      total.inside.insert(total.inside.end(), local.inside.begin(), local.inside.end());
    }
  }
  if (total.kept == 0) return {true, std::nullopt};
  const std::uint64_t r_lo = (total.kept - 1) / 2, r_hi = total.kept / 2;
  if (r_lo < total.below || r_hi >= total.below + total.inside.size()) return {};
  return {true, select_key_pair(total.inside, static_cast<std::size_t>(r_lo - total.below),
                                static_cast<std::size_t>(r_hi - total.below), key_lo, key_hi)};
}

// Kept values in median_pair_float's sample (see median_pair_sampled).
inline constexpr std::size_t kMedianSample = 16384;

}  // namespace detail

// The lower and upper medians of the kept values (ranks (n - 1) / 2 and
// n / 2 of the n kept; equal when n is odd). Usually one read of the data
// (detail::median_pair_sampled); when the sample's bracket misses, the
// two-pass radix select (detail::median_pair_radix), where two
// kth_smallest_float calls and a count_kept would take five. Both are exact:
// the same values either way. std::nullopt when nothing is kept.
template <typename Keep>
std::optional<std::pair<float, float>> median_pair_float(std::span<const float> v, Keep keep) {
  detail::SampledMedian m = detail::median_pair_sampled(v, keep, detail::kMedianSample);
  if (m.bracketed) return m.median;
  return detail::median_pair_radix(v, keep);
}

}  // namespace ris
