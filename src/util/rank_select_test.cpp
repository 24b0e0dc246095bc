#include "ris/util/rank_select.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "ris/util/counter_rng.h"

namespace ris {
namespace {

// Every rank of a stream with negatives, zeros of both signs, duplicates and
// values that share their top 16 bits equals std::nth_element's.
TEST(FloatRankSelect, EqualsNthElement) {
  std::vector<float> v;
  CounterRng rng(3, 0, 0, 0);
  for (int i = 0; i < 3000; ++i) v.push_back(static_cast<float>(rng.normal() * 100.0));
  for (int i = 0; i < 500; ++i) v.push_back(1000.0f + static_cast<float>(i) * 1e-4f);  // one bucket
  for (int i = 0; i < 50; ++i) v.push_back(42.0f);
  v.push_back(0.0f);
  v.push_back(-0.0f);
  v.push_back(-1e30f);
  v.push_back(1e-30f);
  const std::vector<std::uint64_t> ranks = {0, 1, 1000, v.size() / 2, v.size() - 2, v.size() - 1};
  FloatRankSelect sel;
  for (float x : v) sel.count(x);
  EXPECT_EQ(sel.total(), v.size());
  sel.select(ranks);
  for (auto it = v.rbegin(); it != v.rend(); ++it) sel.refine(*it);
  for (std::size_t i = 0; i < ranks.size(); ++i) {
    std::vector<float> w = v;
    std::nth_element(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(ranks[i]), w.end());
    EXPECT_EQ(sel.value(i), w[ranks[i]]) << "rank " << ranks[i];
  }
}

TEST(FloatRankSelect, KeyPreservesOrder) {
  const std::vector<float> sorted = {-1e30f, -2.0f, -1.0f, -1e-30f, 0.0f,
                                     1e-30f, 1.0f,  3.0f,  1e30f};
  for (std::size_t i = 1; i < sorted.size(); ++i)
    EXPECT_LT(FloatRankSelect::key(sorted[i - 1]), FloatRankSelect::key(sorted[i]));
}

}  // namespace
}  // namespace ris
