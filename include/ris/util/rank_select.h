// Exact order statistics (the k-th smallest value) of a stream of floats too
// large to hold, in two passes with 2 x 65,536 counters: pass 1 counts the
// values by their top 16 bits (sign, exponent and 7 mantissa bits, in an
// order-preserving encoding); pass 2 counts, within the bucket holding each
// wanted rank, the low 16 bits. The result is the very float that
// std::nth_element would put at that rank (radix selection; Knuth, TAOCP
// vol. 3, section 5.2.5).
//
// A streamed run (ris/sim/slar_stream.h) takes the median elevation (the
// ground-range reference height) and the median mean power (the auto
// greytone reference) this way, so they equal the in-memory medians, which
// ris/util/float_select.h finds by the same method (same key encoding) over
// an array in memory. This class is its form for values that arrive in
// blocks and cannot be held.
//
// Example:
//   ris::FloatRankSelect sel;
//   for (float v : pass1) sel.count(v);              // NaN must not be passed
//   sel.select({sel.total() / 2});
//   for (float v : pass2) sel.refine(v);            // the same values again
//   float median = sel.value(0);
#pragma once

#include <cstdint>
#include <vector>

namespace ris {

class FloatRankSelect {
 public:
  FloatRankSelect();

  // Pass 1: one value (not NaN).
  void count(float v) { ++top_[key(v) >> 16]; }
  // Adds another selector's pass-1 counts (per-thread selectors).
  void merge_counts(const FloatRankSelect& other);
  std::uint64_t total() const;

  // Between the passes: the ranks wanted (0-based, each < total()).
  void select(const std::vector<std::uint64_t>& ranks);
  // Pass 2: the same values again, in any order.
  void refine(float v);
  // After pass 2: the value at ranks[i].
  float value(std::size_t i) const;

  // The counters of the pass under way (before select(): pass 1's bucket
  // counts; after: pass 2's counts for each wanted rank, one after the
  // other), so that selectors that each counted a part of the values (the
  // ranks of a distributed run: ris/util/process_group.h) are summed
  // exactly: add every part's counters element-wise and set the sums on
  // each (then select() and value() give what one selector of all the
  // values would).
  std::vector<std::uint64_t> counters() const;
  void set_counters(const std::vector<std::uint64_t>& sums);

  // Order-preserving encoding of a float's bits (detail::float_order_key).
  static std::uint32_t key(float v);

 private:
  struct Wanted {
    std::uint64_t rank = 0;
    std::uint32_t bucket = 0;        // top 16 bits
    std::uint64_t below = 0;         // values in lower buckets
    std::vector<std::uint64_t> low;  // pass-2 counts of the low 16 bits
  };
  std::vector<std::uint64_t> top_;
  std::vector<Wanted> wanted_;
};

}  // namespace ris
