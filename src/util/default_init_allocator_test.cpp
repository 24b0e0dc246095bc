#include "ris/util/default_init_allocator.h"

#include <gtest/gtest.h>

#include <vector>

namespace ris {
namespace {

// Growing keeps the old elements; values given explicitly are constructed as
// with std::allocator (assign, push_back, resize with a value).
TEST(DefaultInitAllocator, BehavesAsAVectorExceptForTheFill) {
  std::vector<double, DefaultInitAllocator<double>> v;
  v.assign(3, 0.0);
  v.push_back(2.5);
  v.resize(1000);  // new elements: whatever the memory held
  for (std::size_t i = 4; i < v.size(); ++i) v[i] = double(i);
  EXPECT_EQ(v[0], 0.0);
  EXPECT_EQ(v[3], 2.5);
  EXPECT_EQ(v[999], 999.0);
  v.resize(1005, 7.0);
  EXPECT_EQ(v[1004], 7.0);
  v.erase(v.begin(), v.begin() + 3);
  EXPECT_EQ(v[0], 2.5);
  EXPECT_EQ(v.size(), 1002u);
}

}  // namespace
}  // namespace ris
