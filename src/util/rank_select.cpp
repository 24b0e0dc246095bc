#include "ris/util/rank_select.h"

#include "ris/util/error.h"
#include "ris/util/float_select.h"

namespace ris {

FloatRankSelect::FloatRankSelect() : top_(65536, 0) {}

std::uint32_t FloatRankSelect::key(float v) {
  return detail::float_order_key(v);
}

void FloatRankSelect::merge_counts(const FloatRankSelect& other) {
  for (std::size_t i = 0; i < top_.size(); ++i) top_[i] += other.top_[i];
}

std::uint64_t FloatRankSelect::total() const {
  std::uint64_t n = 0;
  for (std::uint64_t c : top_) n += c;
  return n;
}

std::vector<std::uint64_t> FloatRankSelect::counters() const {
  if (wanted_.empty()) return top_;
  std::vector<std::uint64_t> all;
  all.reserve(wanted_.size() * 65536);
  for (const Wanted& w : wanted_) all.insert(all.end(), w.low.begin(), w.low.end());
  return all;
}

void FloatRankSelect::set_counters(const std::vector<std::uint64_t>& sums) {
  if (wanted_.empty()) {
    RIS_CHECK(sums.size() == top_.size());
    top_ = sums;
    return;
  }
  RIS_CHECK(sums.size() == wanted_.size() * 65536);
  for (std::size_t i = 0; i < wanted_.size(); ++i) {
    const auto at = static_cast<std::ptrdiff_t>(i * 65536);
    wanted_[i].low.assign(sums.begin() + at, sums.begin() + at + 65536);
  }
}

void FloatRankSelect::select(const std::vector<std::uint64_t>& ranks) {
  wanted_.clear();
  for (std::uint64_t rank : ranks) {
    Wanted w;
    w.rank = rank;
    std::uint64_t below = 0;
    std::uint32_t b = 0;
    while (b < 65536 && below + top_[b] <= rank) below += top_[b++];
    RIS_CHECK(b < 65536);  // rank < total()
    w.bucket = b;
    w.below = below;
    w.low.assign(65536, 0);
    wanted_.push_back(std::move(w));
  }
}

void FloatRankSelect::refine(float v) {
  const std::uint32_t k = key(v);
  for (Wanted& w : wanted_)
    if ((k >> 16) == w.bucket) ++w.low[k & 0xFFFFu];
}

float FloatRankSelect::value(std::size_t i) const {
  const Wanted& w = wanted_.at(i);
  std::uint64_t below = w.below;
  std::uint32_t lo = 0;
  while (lo < 65536 && below + w.low[lo] <= w.rank) below += w.low[lo++];
  RIS_CHECK(lo < 65536);  // pass 2 saw the same values as pass 1
  return detail::float_from_order_key((w.bucket << 16) | lo);
}

}  // namespace ris
