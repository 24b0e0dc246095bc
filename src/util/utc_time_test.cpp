#include "ris/util/utc_time.h"

#include <gtest/gtest.h>

namespace ris {
namespace {

TEST(UtcTime, ParsesProductFormsAndSubtracts) {
  const auto epoch = parse_seconds_since("seconds since 2012-07-15 14:36:47");
  ASSERT_TRUE(epoch);
  const auto start = parse_utc("2012-07-17T14:36:47");
  ASSERT_TRUE(start);
  EXPECT_DOUBLE_EQ(start->seconds_since(*epoch), 172800.0);  // winnipeg.h5's first line
  const auto a = parse_utc("2022-01-04T17:05:58.268589");
  const auto b = parse_utc("2021-12-31T23:59:59.5Z");
  ASSERT_TRUE(a && b);
  EXPECT_NEAR(a->seconds_since(*b), 3 * 86400.0 + 17 * 3600.0 + 5 * 60.0 + 58.268589 + 0.5, 1e-9);
  EXPECT_EQ(a->iso(), "2022-01-04T17:05:58.268589");
  EXPECT_EQ(parse_utc("1970-01-01T00:00:00")->days, 0);
}

TEST(UtcTime, RejectsMalformedText) {
  EXPECT_FALSE(parse_utc("2022-01-04"));
  EXPECT_FALSE(parse_utc("2022-13-04T00:00:00"));
  EXPECT_FALSE(parse_utc("2022-01-04T00:00:00.x"));
  EXPECT_FALSE(parse_seconds_since("meters"));
}

}  // namespace
}  // namespace ris
