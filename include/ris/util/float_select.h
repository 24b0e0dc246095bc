// The k-th smallest of a large set of floats in two parallel counting passes
// (a radix select on the floats' bit patterns), without copying or reordering
// the data: what std::nth_element gives on a filtered copy, at a fraction of
// the cost for millions of values (the ground-range reference height is the
// median of every scene cell; the automatic greytone reference the median of
// every pixel).
//
// A float's bits, with the sign bit flipped for positive values and all bits
// flipped for negative ones, order as the floats do (-0 just below +0). Pass
// 1 counts the top 16 bits of the kept values, which finds the bucket holding
// rank k; pass 2 counts the low 16 bits within that bucket. Each pass is one
// read of the data, split over OpenMP threads with per-thread counts, so the
// result does not depend on the thread count.
//
// Example (the median of the finite cells with data):
//   auto keep = [&](std::size_t i) { return valid[i] && std::isfinite(h[i]); };
//   std::size_t n = ris::count_kept(h.size(), keep);
//   if (n) float m = *ris::kth_smallest_float(h, n / 2, keep);
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace ris {

namespace detail {

inline std::uint32_t float_order_key(float f) {
  std::uint32_t b = 0;
  std::memcpy(&b, &f, sizeof b);
  return (b & 0x80000000u) ? ~b : (b | 0x80000000u);
}

inline float float_from_order_key(std::uint32_t k) {
  const std::uint32_t b = (k & 0x80000000u) ? (k & 0x7fffffffu) : ~k;
  float f = 0.0f;
  std::memcpy(&f, &b, sizeof f);
  return f;
}

// Counts keys (>> shift) & 0xffff of the kept values whose key's top 16 bits
// are `top` (or any, with match_top false) into 65536 buckets.
template <typename Keep>
std::vector<std::uint64_t> count_buckets(std::span<const float> v, Keep keep, int shift,
                                         bool match_top, std::uint32_t top) {
  std::vector<std::uint64_t> total(65536, 0);
  const auto n = static_cast<std::int64_t>(v.size());
#pragma omp parallel
  {
    std::vector<std::uint64_t> local(65536, 0);
#pragma omp for schedule(static)
    for (std::int64_t i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!keep(k)) continue;
      const std::uint32_t key = float_order_key(v[k]);
      if (match_top && (key >> 16) != top) continue;
      ++local[(key >> shift) & 0xffffu];
    }
#pragma omp critical(ris_float_select)
    for (std::size_t b = 0; b < local.size(); ++b) total[b] += local[b];
  }
  return total;
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
  const auto high = detail::count_buckets(v, keep, 16, false, 0);
  std::uint64_t kept = 0;
  for (std::uint64_t c : high) kept += c;
  if (rank >= kept) return std::nullopt;
  const std::uint32_t top = detail::bucket_of_rank(high, rank);
  const auto low = detail::count_buckets(v, keep, 0, true, top);
  const std::uint32_t bottom = detail::bucket_of_rank(low, rank);
  return detail::float_from_order_key((top << 16) | bottom);
}

// The lower and upper medians of the kept values (ranks (n - 1) / 2 and
// n / 2 of the n kept; equal when n is odd) in two passes in all, where two
// kth_smallest_float calls and a count_kept would take five. std::nullopt when
// nothing is kept.
template <typename Keep>
std::optional<std::pair<float, float>> median_pair_float(std::span<const float> v, Keep keep) {
  const auto high = detail::count_buckets(v, keep, 16, false, 0);
  std::uint64_t n = 0;
  for (std::uint64_t c : high) n += c;
  if (n == 0) return std::nullopt;
  std::uint64_t r_lo = (n - 1) / 2, r_hi = n / 2;
  const std::uint32_t t_lo = detail::bucket_of_rank(high, r_lo);
  const std::uint32_t t_hi = detail::bucket_of_rank(high, r_hi);
  // Pass 2: the low 16 bits within the one or two buckets.
  std::vector<std::uint64_t> lo_counts(65536, 0), hi_counts(65536, 0);
  const auto size = static_cast<std::int64_t>(v.size());
#pragma omp parallel
  {
    std::vector<std::uint64_t> a(65536, 0), b(t_hi != t_lo ? 65536 : 0, 0);
#pragma omp for schedule(static)
    for (std::int64_t i = 0; i < size; ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!keep(k)) continue;
      const std::uint32_t key = detail::float_order_key(v[k]);
      const std::uint32_t top = key >> 16;
      if (top == t_lo) ++a[key & 0xffffu];
      if (top == t_hi && t_hi != t_lo) ++b[key & 0xffffu];
    }
#pragma omp critical(ris_float_select)
    {
      for (std::size_t j = 0; j < a.size(); ++j) lo_counts[j] += a[j];
      for (std::size_t j = 0; j < b.size(); ++j) hi_counts[j] += b[j];
    }
  }
  const std::uint32_t b_lo = detail::bucket_of_rank(lo_counts, r_lo);
  const std::uint32_t b_hi = detail::bucket_of_rank(t_hi != t_lo ? hi_counts : lo_counts, r_hi);
  return std::pair{detail::float_from_order_key((t_lo << 16) | b_lo),
                   detail::float_from_order_key((t_hi << 16) | b_hi)};
}

}  // namespace ris
